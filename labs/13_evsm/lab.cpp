// Lab 13: exponential variance shadow maps (EVSM, two moments), beyond the course.
// Demonstrates: warping depth through w = exp(c z) before taking VSM's moments, so Chebyshev's bound
// falls much faster behind an occluder and the light that bleeds through stacked occluders (lab 4) is
// mostly gone at the same settings; the exponent's limit per moments format (RG32F: 42, RG16F: 5). It
// reuses VSM's moments pass, targets and blur (renderer/moments_pass.h): vsm.warp = none is lab 4's VSM
// on the same frame, so one slider compares the two.
// Check: on the stacked-occluder scene (lab 4's), unblurred and blurred at radius 4, the bleeding rate
// and the interior error against VSM with the delta fix at the same settings; on the default scene and
// under a grazing light (elevation 10 deg) the interior errors against the oracle within measured bounds.
#include "grading/lab.h"

#include <cstdio>
#include <string>
#include <utility>

#include "grading/check.h"
#include "labs/vsm_features.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/vsm/evsm_warp.glsl";

// The targets against VSM at the same settings (lab 4's frame). The measured bleeding rates and interior
// errors of both, per case: INSTRUCTOR.md, recorded in docs/measured/lab_13.json.
// The warp alone (delta 0) must cut VSM's bleeding: to a quarter unblurred, to three quarters blurred (what
// is left there is the blur's own spread past the edge band, which no bound removes). With lab 4's cut on
// both, VSM hardly bleeds: EVSM must stay within lab 4's 1 % and not raise the interior error.
constexpr double kMaxBleedingRatioUnblurred = 0.25;
constexpr double kMaxBleedingRatioBlurred = 0.75;
constexpr double kLabDelta = 0.125;  // lab 4's cut
constexpr int kBlurRadius = 4;
struct Target {
  double delta;
  int radius;
  double max_bleeding_ratio;  // EVSM / VSM without the cut (graded when VSM bleeds at all); 0: not graded
};
constexpr Target kTargets[] = {{0.0, 0, kMaxBleedingRatioUnblurred},
                               {0.0, kBlurRadius, kMaxBleedingRatioBlurred},
                               {kLabDelta, 0, 0.0},
                               {kLabDelta, kBlurRadius, 0.0}};
constexpr double kMaxBleeding = 0.01;  // lab 4's bound
constexpr double kMaxInteriorErrorOverVsm = 0.0;
constexpr double kBlurSigma = 2.0;  // lab 4's blurred case: radius 4, sigma 2

ParamSet with_warp(ParamSet p, const char* warp) {
  p.set_from_string("vsm.warp", warp);
  return p;
}

void check_evsm(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const Features hooks = ctx.hooks();

  // 1. The default scene and a grazing light (elevation 10 deg): a hard shadow's interior within lab 1's
  // bounds (the measured errors: docs/measured/lab_13.json).
  grade_default_and_grazing(ctx, result, params, hooks, "lab13");

  // 2. The stacked occluders, against VSM (the same shaders with vsm.warp = none) at the same settings.
  ctx.use_scene(make_stacked_occluders_scene());
  const Bounds view = shadows_on_receiver(
      ctx.scene(), direction_from_angles(params.get_float("light.azimuth"), params.get_float("light.elevation")));
  std::printf("    stacked scene, c = %.3g:  delta  radius  bleeding VSM  EVSM    mae_interior VSM  EVSM     mae_edge VSM  EVSM\n",
              static_cast<double>(params.get(param::vsm_evsm_exponent)));
  for (const Target& t : kTargets) {
    ParamSet p = params;
    p.set("vsm.bleed_delta", t.delta);
    p.set("vsm.blur_radius", t.radius);
    p.set("vsm.blur_sigma", kBlurSigma);
    const std::string tag = std::string(t.delta > 0 ? "stacked_cut_r" : "stacked_nocut_r") + std::to_string(t.radius);
    const auto v = ctx.measure(with_warp(p, "none"), hooks, "lab13_" + tag + "_vsm", &view);
    const auto e = ctx.measure(with_warp(p, "exponential"), hooks, "lab13_" + tag + "_" + impl_name(ctx.impl), &view);
    result.metrics[tag + "_vsm"] = to_json(v.metrics);
    result.metrics[tag] = to_json(e.metrics);
    std::printf("                              %5.3f  %6d  %12.4f  %6.4f  %16.5f  %7.5f  %12.5f  %7.5f\n", t.delta, t.radius,
                v.metrics.bleeding_rate, e.metrics.bleeding_rate, v.metrics.mae_interior, e.metrics.mae_interior,
                v.metrics.mae_edge, e.metrics.mae_edge);
    if (t.max_bleeding_ratio > 0 && v.metrics.bleeding_rate > 0)
      result.criteria.push_back({tag + ".bleeding_ratio_to_vsm", e.metrics.bleeding_rate / v.metrics.bleeding_rate,
                                 Criterion::kAtMost, t.max_bleeding_ratio,
                                 "EVSM's bleeding against VSM's at the same settings (measured targets, lab README)",
                                 "warp depth with a steep increasing function: exp(c * z)."});
    if (t.delta > 0) {
      result.criteria.push_back({tag + ".bleeding_rate", e.metrics.bleeding_rate, Criterion::kAtMost, kMaxBleeding,
                                 "with lab 4's cut, at most 1 % of the shadowed interior bleeds (lab 4's bound)"});
      result.criteria.push_back({tag + ".interior_error_over_vsm", e.metrics.mae_interior - v.metrics.mae_interior,
                                 Criterion::kAtMost, kMaxInteriorErrorOverVsm,
                                 "with lab 4's cut, EVSM's mean interior error is at most VSM's"});
    }
    require_measurable(result, tag, e.metrics);
  }
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "EVSM: exponential variance shadow maps";
  lab.summary = "Warp depth through exp(c z) before the moments: VSM's light bleeding mostly goes.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = vsm_param_specs({"vsm.warp", "vsm.evsm_exponent", "vsm.format", "vsm.min_variance", "vsm.bleed_delta",
                                "vsm.blur_radius", "vsm.blur_sigma"});
  for (auto& spec : lab.params)
    if (spec.key == "vsm.warp") spec.default_value = 1.0;  // exponential
  for (const auto& spec : vsm_lab_bias_params()) lab.params.push_back(spec);
  lab.presets = {
      // The bleeding presets: on the stacked occluders the check grades, the moments blurred (radius 8,
      // sigma 4) so that the light bleeding under the low occluder's shadow edge is wide enough to see.
      {"VSM", "vsm.warp = none: lab 4's VSM with the delta fix, blurred wide, on the stacked occluders.",
       {{"vsm.warp", "none"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}},
       {.provokes = "light bleeding", .fixed_by = "EVSM"},
       {.scene = kStackedOccludersScene, .camera = kStackedBleedingCamera}},
      {"EVSM", "w = exp(42 z) in RG32F.", {{"vsm.warp", "exponential"}, {"vsm.evsm_exponent", "42"}, {"vsm.format", "RG32F"}}},
      {"small c", "c = 5 (the RG16F limit), blurred wide, on the stacked occluders: less sharpening, more bleeding.",
       {{"vsm.evsm_exponent", "5"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}},
       {.provokes = "light bleeding", .fixed_by = "EVSM"},
       {.scene = kStackedOccludersScene, .camera = kStackedBleedingCamera}},
      {"half floats", "RG16F (c is clamped to 5), blurred wide, on the stacked occluders.",
       {{"vsm.format", "RG16F"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}},
       {.provokes = "light bleeding", .fixed_by = "EVSM"},
       {.scene = kStackedOccludersScene, .camera = kStackedBleedingCamera}},
  };
  lab.offered_includes = {};
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.technique = ShadowTechnique::Moments;
    hooks.includes["lab/warp.glsl"] = files.at(0).string();
    hooks.includes["lab/moments.glsl"] = "shaders/vsm/evsm_moments.glsl";
    hooks.includes["lab/visibility.glsl"] = "shaders/vsm/evsm_visibility.glsl";
    return hooks;
  };
  lab.check = check_evsm;
  // EVSM on the benchmark's front, at VSM's radii (lab 4's entries), c = 42 in RG32F.
  for (int r : {0, 2, 4}) lab.bench.push_back({"evsm r" + std::to_string(r), "EVSM", {{"vsm.blur_radius", std::to_string(r)}}, true, true});
  return lab;
}

}  // namespace shadowlab
