// Lab 14: moment shadow maps (MSM, Peters & Klein 2015), beyond the course.
// Demonstrates: four power moments per texel (RGBA32F) instead of VSM's two, read through the
// four-moment Hamburger bound (the student's part: the Hankel solve, the roots, the weights in front), the
// sharpest lower bound on the shadow, which leaks far less than Chebyshev's (two moments); the moment
// bias that keeps the solve defined in float32. No blur (VSM's blurs are two-channel).
// Check: the bound probed on its own against a double-precision reference by another route; on the
// stacked-occluder scene (lab 4's frame) the bleeding rate and the interior error
// against VSM (lab 4's solution) at the same bias, without and with lab 4's cut; on the default scene
// and under a grazing light (elevation 10 deg) lab 1's hard-shadow bounds.
#include "grading/lab.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "grading/check.h"
#include "grading/probe.h"
#include "labs/vsm_features.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/msm/hamburger.glsl";

// Against VSM at the same settings (no blur; lab 4's frame; the measured figures of both: INSTRUCTOR.md,
// recorded in docs/measured/lab_14.json). MSM's bleeding must be at most a quarter of VSM's without
// the cut and at most 1 % (lab 4's bound); its interior error at most VSM's without the cut.
constexpr double kMaxBleedingRatioToVsm = 0.25;
constexpr double kMaxBleeding = 0.01;
constexpr double kMaxInteriorErrorOverVsm = 0.0;
constexpr double kVsmDeltas[] = {0.0, 0.125};

// The probe (grading/probe.h): msm_hamburger on the biased moments of distributions of two to four depths
// in [0, 1] (random weights), mixed with (0.5, 0.5, 0.5, 0.5) by each of kProbeAlphas, at receivers over
// [0, 1] and just in front of and behind each depth; against the bound computed in double by another route
// (the 3 x 3 system solved by Cramer's rule, the support points' weights from their Vandermonde system).
// A case counts as "in front" where the bound is below kSideMargin, "behind" above 1 - kSideMargin, else
// "partial"; kProbeCasesPerSide of each.
constexpr double kProbeAlphas[] = {1e-3, 1e-2};
constexpr int kProbeCasesPerSide = 200;
constexpr double kSideMargin = 0.02;
constexpr double kProbeTolerance = 2e-3;
constexpr double kMaxProbeMismatch = 0.0;

double hamburger_reference(const glm::dvec4& b, double z) {
  const glm::dmat3 B(1.0, b.x, b.y, b.x, b.y, b.z, b.y, b.z, b.w);
  const double det = glm::determinant(B);
  auto replaced = [&](int column) {
    glm::dmat3 m = B;
    m[column] = glm::dvec3(1.0, z, z * z);
    return glm::determinant(m) / det;
  };
  const double c0 = replaced(0), c1 = replaced(1), c2 = replaced(2);
  const double p = c1 / c2, q = c0 / c2, r = std::sqrt(std::max(p * p / 4.0 - q, 0.0));
  const double z1 = -p / 2.0 - r, z2 = -p / 2.0 + r;
  // Weights of the support points z1, z2 (and z) that match the moments 1, b.x, b.y.
  const double w1 = (b.y - b.x * (z + z2) + z * z2) / ((z1 - z) * (z1 - z2));
  const double w2 = (b.y - b.x * (z + z1) + z * z1) / ((z2 - z) * (z2 - z1));
  return std::clamp((z1 < z ? w1 : 0.0) + (z2 < z ? w2 : 0.0), 0.0, 1.0);
}

// The probe's cases: in0 the biased moments, in1.x the receiver's depth; kind 0: in front of every depth
// (about 0), 1: partial, 2: behind (about 1).
std::vector<ProbeCase> hamburger_cases(std::mt19937 rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ProbeCase> cases;
  int count[3] = {0, 0, 0};
  for (int tries = 0; tries < 100000 && (count[0] < kProbeCasesPerSide || count[1] < kProbeCasesPerSide ||
                                         count[2] < kProbeCasesPerSide); ++tries) {
    const int points = 2 + static_cast<int>(rng() % 3);
    glm::dvec4 m(0.0);
    double total = 0.0, depths[4];
    for (int i = 0; i < points; ++i) {
      const double w = 0.1 + unit(rng);
      depths[i] = unit(rng);
      const double d = depths[i];
      m += w * glm::dvec4(d, d * d, d * d * d, d * d * d * d);
      total += w;
    }
    const double alpha = kProbeAlphas[rng() % std::size(kProbeAlphas)];
    const glm::dvec4 b = glm::mix(m / total, glm::dvec4(0.5), alpha);
    const double near = depths[rng() % static_cast<unsigned>(points)] + (unit(rng) < 0.5 ? -0.01 : 0.01);
    const float z = static_cast<float>(tries % 2 ? unit(rng) : std::clamp(near, 0.0, 1.0));
    const glm::vec4 bf(b);
    const double want = hamburger_reference(glm::dvec4(bf), z);
    const int side = want < kSideMargin ? 0 : want > 1.0 - kSideMargin ? 2 : 1;
    if (!std::isfinite(want) || count[side] >= kProbeCasesPerSide) continue;
    ++count[side];
    cases.push_back({bf, glm::vec4(z, 0.0f, 0.0f, 0.0f), want, side});
  }
  return cases;
}

void probe_hamburger(CheckContext& ctx, CheckResult& result) {
  const ProbeTally t = probe_kinds(
      result, ctx.hooks(), "shaders/probe/msm_hamburger.frag", hamburger_cases(ctx.held_out_rng()),
      {{"hamburger.front_mismatch", "a receiver in front of every depth the moments allow is not shadowed: about 0 there."},
       {"hamburger.partial_mismatch",
        "solve B c = (1, z, z^2) with the Hankel matrix B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]], take the roots "
        "z1 <= z2 of c0 + c1 x + c2 x^2, and return the weight of the roots strictly in front of z (the weight at z "
        "itself is not in front): the least shadow these moments allow."},
       {"hamburger.behind_mismatch",
        "behind both roots the shadow is 1 minus the weight at z itself: close to 1 when z is far behind the depths."}},
      kProbeTolerance, kMaxProbeMismatch,
      "probe: msm_hamburger on the biased moments of two to four depths against the bound in double, within 0.002");
  result.metrics["hamburger_probe"] = {{"front_cases", t.cases[0]}, {"partial_cases", t.cases[1]},
                                       {"behind_cases", t.cases[2]}, {"worst_error", t.worst_error}};
}

void check_msm(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const Features hooks = ctx.hooks();
  probe_hamburger(ctx, result);

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
                                 "the Hamburger bound from all four moments, not Chebyshev's from two (see hamburger.*)."});
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
  lab.summary = "Four power moments and the Hamburger bound, the sharpest lower bound on the shadow: far less bleeding than "
                "Chebyshev's.";
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
    hooks.includes["lab/hamburger.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_msm;
  lab.bench.push_back({"msm", "MSM", {}, true, true});
  return lab;
}

}  // namespace shadowlab
