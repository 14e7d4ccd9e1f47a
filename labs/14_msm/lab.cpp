// Lab 14: moment shadow maps (MSM, Peters & Klein 2015), beyond the course.
// Demonstrates: four power moments per texel (RGBA32F) instead of VSM's two, read through the
// four-moment Hamburger bound, which is sharp where Chebyshev's bound (two moments) bleeds; the moment
// bias that keeps the solve defined in float32. No blur (VSM's blurs are two-channel).
// Check: on the stacked-occluder scene (lab 4's frame) the bleeding rate and the interior error
// against VSM (lab 4's solution) at the same bias, without and with lab 4's cut; on the default scene
// and under a grazing light (elevation 10 deg) lab 1's hard-shadow bounds.
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
constexpr const char* kSolution = "shaders/msm/power_moments.glsl";

// Against VSM at the same settings (no blur; lab 4's frame; the measured figures of both: INSTRUCTOR.md,
// recorded in docs/measured/lab_14.json). MSM's bleeding must be at most a quarter of VSM's without
// the cut and at most 1 % (lab 4's bound); its interior error at most VSM's without the cut.
constexpr double kMaxBleedingRatioToVsm = 0.25;
constexpr double kMaxBleeding = 0.01;
constexpr double kMaxInteriorErrorOverVsm = 0.0;
constexpr double kVsmDeltas[] = {0.0, 0.125};

void check_msm(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const Features hooks = ctx.hooks();

  // 1. The default scene and a grazing light: a hard shadow's interior within lab 1's bounds.
  grade_default_and_grazing(ctx, result, params, hooks, "lab14");

  // 2. The stacked occluders: MSM, then VSM (the renderer's own test, lab 4's solution) on the same frame,
  // without and with the cut.
  ctx.use_scene(make_stacked_occluders_scene());
  const Bounds view = shadows_on_receiver(
      ctx.scene(), direction_from_angles(params.get_float("light.azimuth"), params.get_float("light.elevation")));
  const auto m = ctx.measure(params, hooks, std::string("lab14_stacked_") + impl_name(ctx.impl), &view);
  result.metrics["stacked"] = to_json(m.metrics);
  result.criteria.push_back({"stacked.bleeding_rate", m.metrics.bleeding_rate, Criterion::kAtMost, kMaxBleeding,
                             "at most 1 % of the shadowed interior bleeds (lab 4's bound)"});
  require_measurable(result, "stacked", m.metrics);
  const Features vsm = vsm_features();
  std::printf("    stacked scene: MSM bleeding %.4f, mae_interior %.5f, mae_edge %.5f\n", m.metrics.bleeding_rate,
              m.metrics.mae_interior, m.metrics.mae_edge);
  for (double delta : kVsmDeltas) {
    ParamSet p = params;
    p.declare(vsm_param_specs({"vsm.bleed_delta"}).at(0));
    p.set("vsm.bleed_delta", delta);
    const std::string tag = delta > 0 ? "stacked_vsm_cut" : "stacked_vsm_nocut";
    const auto v = ctx.measure(p, vsm, "lab14_" + tag, &view);
    result.metrics[tag] = to_json(v.metrics);
    std::printf("    VSM, delta %.3f: bleeding %.4f, mae_interior %.5f, mae_edge %.5f\n", delta, v.metrics.bleeding_rate,
                v.metrics.mae_interior, v.metrics.mae_edge);
    if (delta == 0.0 && v.metrics.bleeding_rate > 0)
      result.criteria.push_back({"stacked.bleeding_ratio_to_vsm", m.metrics.bleeding_rate / v.metrics.bleeding_rate,
                                 Criterion::kAtMost, kMaxBleedingRatioToVsm,
                                 "MSM bleeds at most a quarter as much as VSM without the cut",
                                 "store all four power moments: z, z^2, z^3, z^4."});
    // With the cut VSM's interior is exact on this frame (every bound below delta is cut to 0): MSM,
    // without one, is measured against VSM without it and only reported against the cut.
    if (delta == 0.0)
      result.criteria.push_back({"stacked.interior_error_over_vsm", m.metrics.mae_interior - v.metrics.mae_interior,
                                 Criterion::kAtMost, kMaxInteriorErrorOverVsm,
                                 "MSM's mean interior error is at most VSM's without the cut"});
  }
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "MSM: moment shadow maps";
  lab.summary = "Four power moments and the Hamburger bound: sharper than Chebyshev's where VSM bleeds.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = vsm_param_specs({"vsm.msm_moment_bias"});
  for (const auto& spec : vsm_lab_bias_params()) lab.params.push_back(spec);
  lab.presets = {
      {"paper", "alpha = 3e-5, the paper's moment bias.", {{"vsm.msm_moment_bias", "3e-5"}}},
      {"large bias", "alpha = 3e-3: the bound softens and light bleeds again.", {{"vsm.msm_moment_bias", "0.003"}},
       {.provokes = "light bleeding", .fixed_by = "paper"}, {.scene = kStackedOccludersScene, .camera = kStackedBleedingCamera}},
  };
  lab.offered_includes = {};
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.technique = ShadowTechnique::MomentShadowMaps;
    hooks.includes["lab/msm_moments.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_msm;
  lab.bench.push_back({"msm", "MSM", {}, true, true});
  return lab;
}

}  // namespace shadowlab
