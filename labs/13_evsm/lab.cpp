// Lab 13: exponential variance shadow maps (EVSM, Lauritzen & McCool 2008), beyond the course.
// Demonstrates: warping depth through two increasing functions, w+ = exp(c+ z) and w- = -exp(-c- z), before
// taking VSM's moments (four moments, RGBA), and taking the smaller of the two Chebyshev bounds, so the light
// that bleeds through stacked occluders (lab 4) is mostly gone at the same settings; the exponents' limit per
// moments format (32-bit floats: 42, 16-bit: 5). It reuses VSM's moments pass, targets and blur
// (renderer/moments_pass.h): vsm.warp = none is lab 4's VSM on the same frame, so one choice compares the two.
// Check: the warps probed on their own over z in [0, 1] and exponents 1-42 against exp(), the two-sided bound
// probed on moments of two-depth distributions against the CPU bound; on the stacked-occluder scene (lab 4's),
// unblurred and blurred at radius 4, the bleeding rate and the interior error against VSM at the same settings,
// and the blurred bleeding again at other exponents and in 16-bit floats; on the default scene and under a
// grazing light (elevation 10 deg) the interior errors against the oracle within measured bounds.
#include "grading/lab.h"

#include <cstdio>
#include <string>
#include <utility>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "grading/check.h"
#include "grading/probe.h"
#include "labs/vsm_features.h"
#include "core/vsm_params.h"
#include "renderer/moments_pass.h"

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
// With the cut and the blur, EVSM's sharper bound darkens lit pixels next to the blurred edge a little more
// than VSM's (the solution: +0.000027 mean interior error, measured): a margin of 0.0001.
constexpr double kMaxInteriorErrorOverVsm = 1e-4;
constexpr double kBlurSigma = 2.0;  // lab 4's blurred case: radius 4, sigma 2
// Held-out exponents and formats, blurred at radius 4 without the cut: EVSM's bleeding against VSM's in the
// same format (16-bit floats clamp both exponents to 5), at the blurred case's limit (kMaxBleedingRatioBlurred;
// the measured ratios: INSTRUCTOR.md).
struct HeldOut {
  const char* tag;
  const char* format;
  double positive, negative;
};
constexpr HeldOut kHeldOut[] = {{"held_out_c20_c5", "RG32F", 20.0, 5.0},
                                {"held_out_c10_c30", "RG32F", 10.0, 30.0},
                                {"held_out_half", "RG16F", 42.0, 42.0}};

ParamSet with_warp(ParamSet p, const char* warp) {
  p.set_from_string("vsm.warp", warp);
  return p;
}

// The probes (grading/probe.h). The warps: z over [0, 1] (a grid and its ends) at exponents 1 to 42, each
// warp against exp() in double within kWarpRelative (GLSL's exp is accurate to 3 + 2|x| ulp: 1e-5 at x = 42).
constexpr float kProbeExponents[] = {1.0f, 2.5f, 5.0f, 10.0f, 20.0f, 31.0f, 42.0f};
constexpr int kWarpDepths = 33;        // z = 0, 1/32, ..., 1
constexpr double kWarpRelative = 1e-4;
// The bound: moments of two-depth distributions (both warps, in double, stored as float32), receivers in
// front of, between and behind the two depths; kept when each warp's variance is at least kMinRelativeVariance
// of its E[w^2] (so float32 computes it to 1e-4) and c- z stays below kMaxNegativeArgument (w-^2 a normal
// float). A case counts for the warp whose bound is smaller by kSideMargin (or as lit when both are 1).
constexpr int kBoundCasesPerSide = 200;
constexpr double kMinRelativeVariance = 1e-2;
constexpr double kMaxNegativeArgument = 30.0;
constexpr double kSideMargin = 0.02;
constexpr double kBoundTolerance = 1e-3;
constexpr double kMaxProbeMismatch = 0.0;  // cases off by more than the tolerance: none

double one_sided(double m1, double m2, double w) {
  if (w <= m1) return 1.0;
  const double variance = std::max(m2 - m1 * m1, 0.0);
  return variance / (variance + (w - m1) * (w - m1));
}

void probe_warp(CheckContext& ctx, CheckResult& result) {
  ProbeRequest request;
  request.fragment = "shaders/probe/evsm_warp.frag";
  for (int i = 0; i < kWarpDepths; ++i)
    for (std::size_t a = 0; a < std::size(kProbeExponents); ++a) {
      // c- runs through the exponents in another order, so that no case has c+ = c- but the first.
      const float cn = kProbeExponents[(a * 3 + static_cast<std::size_t>(i)) % std::size(kProbeExponents)];
      request.in0.push_back({static_cast<float>(i) / (kWarpDepths - 1), kProbeExponents[a], cn, 0.0f});
    }
  for (int component : {0, 1})
    request.passes.push_back([component](GLuint program) { set_uniform(program, "u_component", component); });
  const auto v = run_probe(ctx.hooks(), request);
  const char* names[2] = {"warp.positive_mismatch", "warp.negative_mismatch"};
  const char* advice[2] = {"w+ = exp(c+ z) with c+ = c.x: e to the power c+ z (exp, not exp2), nothing added or subtracted.",
                           "w- = -exp(-c- z) with c- = c.y: minus e to the power -c- z, increasing in z like w+."};
  nlohmann::json probe = {{"cases", request.in0.size()}};
  for (int k = 0; k < 2; ++k) {
    int wrong = 0, first = -1;
    for (std::size_t i = 0; i < request.in0.size(); ++i) {
      const glm::vec4& in = request.in0[i];
      const double want = k == 0 ? std::exp(double(in.y) * in.x) : -std::exp(-double(in.z) * in.x);
      const double got = v[static_cast<std::size_t>(k)][i];
      const bool bad = !(std::abs(got - want) <= kWarpRelative * std::abs(want));  // NaN is wrong
      wrong += bad;
      if (bad && first < 0) first = static_cast<int>(i);
    }
    std::string why = advice[k];
    if (first >= 0) {
      const glm::vec4& in = request.in0[static_cast<std::size_t>(first)];
      char e[200];
      std::snprintf(e, sizeof e, " For example z = %.4g, c = (%.3g, %.3g): returned %.6g, expected %.6g.", in.x, in.y, in.z,
                    v[static_cast<std::size_t>(k)][static_cast<std::size_t>(first)],
                    k == 0 ? std::exp(double(in.y) * in.x) : -std::exp(-double(in.z) * in.x));
      why += e;
    }
    probe[k == 0 ? "positive_wrong" : "negative_wrong"] = wrong;
    result.criteria.push_back({names[k], static_cast<double>(wrong) / static_cast<double>(request.in0.size()),
                               Criterion::kAtMost, kMaxProbeMismatch,
                               "probe: evsm_warp at z = 0..1 (33 depths) and exponents 1-42 against exp() in double, "
                               "within 1e-4 relative",
                               why});
  }
  result.metrics["warp_probe"] = probe;
}

// The bound probe's cases: in0 the moments, in1 the receiver's warped depths; kind 0: lit (both bounds 1),
// 1: the positive warp's bound is the smaller, 2: the negative's.
std::vector<ProbeCase> bound_cases(std::mt19937 rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ProbeCase> cases;
  int count[3] = {0, 0, 0};
  for (int tries = 0; tries < 200000 && (count[0] < kBoundCasesPerSide || count[1] < kBoundCasesPerSide ||
                                         count[2] < kBoundCasesPerSide); ++tries) {
    const double cp = kProbeExponents[rng() % std::size(kProbeExponents)];
    const double cn = kProbeExponents[rng() % std::size(kProbeExponents)];
    const double top = std::min(1.0, kMaxNegativeArgument / cn);
    const double z1 = top * unit(rng), z2 = std::min(top, z1 + 0.3 * unit(rng)), a = 0.1 + 0.8 * unit(rng);
    const double zr = std::clamp(z1 - 0.1 + (z2 - z1 + 0.2) * unit(rng), 0.0, top);
    auto f = [](double x) { return static_cast<double>(static_cast<float>(x)); };
    const double p1 = std::exp(cp * z1), p2 = std::exp(cp * z2), n1 = -std::exp(-cn * z1), n2 = -std::exp(-cn * z2);
    const glm::dvec4 m{f(a * p1 + (1 - a) * p2), f(a * p1 * p1 + (1 - a) * p2 * p2), f(a * n1 + (1 - a) * n2),
                       f(a * n1 * n1 + (1 - a) * n2 * n2)};
    const glm::dvec2 w{f(std::exp(cp * zr)), f(-std::exp(-cn * zr))};
    if (m.y - m.x * m.x < kMinRelativeVariance * m.y || m.w - m.z * m.z < kMinRelativeVariance * m.w) continue;
    const double pos = one_sided(m.x, m.y, w.x), neg = one_sided(m.z, m.w, w.y);
    const int side = pos == 1.0 && neg == 1.0 ? 0 : pos < neg - kSideMargin ? 1 : neg < pos - kSideMargin ? 2 : -1;
    if (side < 0 || count[side] >= kBoundCasesPerSide) continue;
    ++count[side];
    cases.push_back({glm::vec4(m), glm::vec4(w, 0.0, 0.0), std::min(pos, neg), side});
  }
  return cases;
}

void probe_bound(CheckContext& ctx, CheckResult& result) {
  const ProbeTally t = probe_kinds(
      result, ctx.hooks(), "shaders/probe/evsm_bound.frag", bound_cases(ctx.held_out_rng()),
      {{"bound.lit_mismatch", "a receiver in front of both warps' means (w <= E[w] for each) is fully lit: 1."},
       {"bound.positive_mismatch",
        "behind the mean, each warp's bound is sigma^2 / (sigma^2 + (w - mu)^2) with sigma^2 = E[w^2] - E[w]^2 of that "
        "warp's pair; both are upper bounds on the light, so return the smaller."},
       {"bound.negative_mismatch",
        "the negative warp's pair (moments.zw, w.y) gives its own bound, the smaller one where the occluders are near the "
        "light: take the minimum of both warps' bounds, with no depth-variance clamp on the negative warp's tiny "
        "variances."}},
      kBoundTolerance, kMaxProbeMismatch,
      "probe: evsm_bound on the moments of two-depth distributions against the CPU bound, within 1e-3");
  result.metrics["bound_probe"] = {{"lit_cases", t.cases[0]}, {"positive_cases", t.cases[1]}, {"negative_cases", t.cases[2]},
                                   {"worst_error", t.worst_error}};
}

void check_evsm(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const Features hooks = ctx.hooks();
  probe_warp(ctx, result);
  probe_bound(ctx, result);

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
                                 "with lab 4's cut, EVSM's mean interior error is at most VSM's + 0.0001"});
    }
    require_measurable(result, tag, e.metrics);
  }
  // 3. Held-out exponents and formats: the blurred, uncut case again.
  for (const HeldOut& h : kHeldOut) {
    ParamSet p = params;
    p.set("vsm.bleed_delta", 0.0);
    p.set("vsm.blur_radius", kBlurRadius);
    p.set("vsm.blur_sigma", kBlurSigma);
    p.set_from_string("vsm.format", h.format);
    p.set("vsm.evsm_exponent", h.positive);
    p.set("vsm.evsm_negative_exponent", h.negative);
    const std::string tag = h.tag;
    const auto v = ctx.measure(with_warp(p, "none"), hooks, "lab13_" + tag + "_vsm", &view);
    const auto e = ctx.measure(with_warp(p, "exponential"), hooks, "lab13_" + tag + "_" + impl_name(ctx.impl), &view);
    result.metrics[tag + "_vsm"] = to_json(v.metrics);
    result.metrics[tag] = to_json(e.metrics);
    const glm::vec2 c = evsm_exponents(with_warp(p, "exponential"));
    std::printf("    %s (%s, c+ %.3g, c- %.3g), radius %d: bleeding VSM %.4f  EVSM %.4f\n", h.tag, h.format, c.x, c.y,
                kBlurRadius, v.metrics.bleeding_rate, e.metrics.bleeding_rate);
    if (v.metrics.bleeding_rate > 0)
      result.criteria.push_back({tag + ".bleeding_ratio_to_vsm", e.metrics.bleeding_rate / v.metrics.bleeding_rate,
                                 Criterion::kAtMost, kMaxBleedingRatioBlurred,
                                 "held-out exponents and formats: EVSM's bleeding against VSM's in the same format "
                                 "(measured targets, lab README)",
                                 "use the exponents you are given (c.x for the positive warp, c.y for the negative)."});
    require_measurable(result, tag, e.metrics);
  }
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "EVSM: exponential variance shadow maps";
  lab.summary = "Warp depth through exp(c+ z) and -exp(-c- z) before the moments, take the smaller bound: VSM's light "
                "bleeding mostly goes.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = vsm_param_specs({"vsm.warp", "vsm.evsm_exponent", "vsm.evsm_negative_exponent", "vsm.format", "vsm.min_variance", "vsm.bleed_delta",
                                "vsm.blur_radius", "vsm.blur_sigma"});
  for (auto& spec : lab.params)
    if (spec.key == "vsm.warp") spec.default_value = 1.0;  // exponential
  for (const auto& spec : vsm_lab_bias_params()) lab.params.push_back(spec);
  // In the window a preset sets only its own keys over the current values (apply_preset): "VSM", "small c"
  // and "half floats" set the warp, the format and the exponents they show, whatever was pressed before.
  lab.presets = {
      // The bleeding presets: on the stacked occluders the check grades, the moments blurred (radius 8,
      // sigma 4) so that the light bleeding under the low occluder's shadow edge is wide enough to see.
      {"VSM", "vsm.warp = none: lab 4's VSM with the delta fix, blurred wide, on the stacked occluders.",
       {{"vsm.warp", "none"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}, {"vsm.format", "RG32F"}},
       {.provokes = "light bleeding", .fixed_by = "EVSM"},
       {.scene = kStackedOccludersScene, .camera = kStackedBleedingCamera}},
      {"EVSM", "w+ = exp(42 z), w- = -exp(-42 z) in RGBA32F.",
       {{"vsm.warp", "exponential"}, {"vsm.evsm_exponent", "42"}, {"vsm.evsm_negative_exponent", "42"}, {"vsm.format", "RG32F"},
        {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}}},
      // At c = 5 (the 16-bit limit) the two warps together hide most of the bleeding: 1.31 % of a 1280x720
      // frame differs from EVSM's, 3.03 % at 2 (cli.preset_contrast asks for 2 %).
      {"small c", "c+ = c- = 2, blurred wide, on the stacked occluders: less sharpening, more bleeding.",
       {{"vsm.evsm_exponent", "2"}, {"vsm.evsm_negative_exponent", "2"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"},
        {"vsm.warp", "exponential"}, {"vsm.format", "RG32F"}},
       {.provokes = "light bleeding", .fixed_by = "EVSM"},
       {.scene = kStackedOccludersScene, .camera = kStackedBleedingCamera}},
      {"half floats", "RGBA16F (both exponents clamped to 5), blurred wide, on the stacked occluders.",
       {{"vsm.format", "RG16F"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}, {"vsm.warp", "exponential"},
        {"vsm.evsm_exponent", "42"}, {"vsm.evsm_negative_exponent", "42"}},
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
  // EVSM on the benchmark's front, at VSM's radii (lab 4's entries), c+ = c- = 42 in RGBA32F.
  for (int r : {0, 2, 4}) lab.bench.push_back({"evsm r" + std::to_string(r), "EVSM", {{"vsm.blur_radius", std::to_string(r)}}, true, true});
  return lab;
}

}  // namespace shadowlab
