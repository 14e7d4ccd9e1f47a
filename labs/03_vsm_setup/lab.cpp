// Lab 3: variance shadow maps, the setup (the course's tasks 3 and 4, and task 5's slope term).
// Demonstrates: the shadow map as an RG32F colour attachment with linear filtering and a D24 depth
// renderbuffer, cleared to (1, 1, 0, 0); the moments (z, z^2 + slope term) written by the shadow pass;
// Chebyshev's bound with a minimum variance in the lit pass; debug quads of E[z], E[z^2] and sigma^2.
// Check: read-backs of the moments against the plain depth map of the same light view, GL's own
// report of the texture's format and filtering, and the lit result's error against the oracle.
#include "grading/lab.h"

#include <cmath>
#include <cstdio>

#include "grading/check.h"
#include "grading/probe.h"
#include "renderer/moments_pass.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace {

constexpr const char* kExerciseMoments = SHADOWLAB_LAB_FOLDER "/exercise_moments.glsl";
constexpr const char* kExerciseChebyshev = SHADOWLAB_LAB_FOLDER "/exercise_chebyshev.glsl";
constexpr const char* kVisibility = SHADOWLAB_LAB_FOLDER "/visibility.glsl";

// The bound for E[z] against the plain depth map: both are gl_FragCoord.z of the same triangle
// stored in 32-bit floats, so anything above float rounding means the moments pass stores something else.
constexpr double kMaxFirstMomentError = 1e-5;
// E[z^2] against z^2 + (1/4)(dz/dx^2 + dz/dy^2) with the derivatives taken as finite differences of
// the depth map. z^2 rounds to within 6e-8 (half an ulp of 1 in float32), each derivative is a
// difference of two depths rounded to 6e-8, and the GPU's own interpolation adds a few ulps more; a
// shader that forgets the slope term or the square is off by far more. The measured worst case and
// the margin: INSTRUCTOR.md ("The second-moment tolerance"), recorded in docs/measured/lab_03.json.
constexpr double kMaxSecondMomentError = 1e-6;
// Two finite differences on either side of a texel count as one plane (the derivative is defined)
// when they agree this well; texels at depth edges and creases are left out of the comparison.
constexpr double kPlanarTolerance = 2e-6;
// RG16F: half-float rounding of values in [0.5, 1] is 4.9e-4, so both moments are held to 1e-3.
constexpr double kMaxMomentErrorHalfFloat = 1e-3;
// Texels that are NaN or Inf, empty texels not holding the clear value, negative variances (RG32F): none.
constexpr double kMaxBadTexels = 0;

struct MomentsComparison {
  double max_first_error = 0.0;
  double max_second_error = 0.0;
  std::size_t second_compared = 0;    // planar texels, where finite differences define dz/dx, dz/dy
  std::size_t second_skipped = 0;     // depth edges and creases
  std::size_t negative_variance = 0;  // E[z^2] - E[z]^2 < 0, in float as a shader computes it
  double min_variance = 1e30;
  std::size_t background = 0;        // texels nothing was drawn into
  std::size_t background_wrong = 0;  // of which not holding the clear value (1, 1)
  std::size_t non_finite = 0;
};

MomentsComparison compare_moments(const std::vector<float>& depth, const std::vector<float>& moments, int n) {
  MomentsComparison c;
  auto d = [&](int x, int y) { return static_cast<double>(depth[static_cast<std::size_t>(y) * n + x]); };
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(n) + static_cast<std::size_t>(x);
      const float m1 = moments[2 * i], m2 = moments[2 * i + 1];
      if (!std::isfinite(m1) || !std::isfinite(m2)) {
        ++c.non_finite;
        continue;
      }
      c.max_first_error = std::max(c.max_first_error, std::abs(static_cast<double>(m1) - d(x, y)));
      const float variance = m2 - m1 * m1;
      c.min_variance = std::min(c.min_variance, static_cast<double>(variance));
      if (variance < 0.0f) ++c.negative_variance;
      if (d(x, y) >= 1.0) {
        ++c.background;
        if (m1 != kMomentsClear[0] || m2 != kMomentsClear[1]) ++c.background_wrong;
        continue;
      }
      if (x == 0 || y == 0 || x == n - 1 || y == n - 1) continue;
      const double fx = d(x + 1, y) - d(x, y), bx = d(x, y) - d(x - 1, y);
      const double fy = d(x, y + 1) - d(x, y), by = d(x, y) - d(x, y - 1);
      const bool neighbours_drawn = d(x + 1, y) < 1.0 && d(x - 1, y) < 1.0 && d(x, y + 1) < 1.0 && d(x, y - 1) < 1.0;
      if (!neighbours_drawn || std::abs(fx - bx) > kPlanarTolerance || std::abs(fy - by) > kPlanarTolerance) {
        ++c.second_skipped;
        continue;
      }
      const double dx = 0.5 * (fx + bx), dy = 0.5 * (fy + by);
      const double expected = d(x, y) * d(x, y) + 0.25 * (dx * dx + dy * dy);
      c.max_second_error = std::max(c.max_second_error, std::abs(static_cast<double>(m2) - expected));
      ++c.second_compared;
    }
  }
  return c;
}

// One frame for read-backs: the shadow passes do not depend on the camera, so a tiny view will do.
void render_for_readback(Renderer& renderer, const Scene& scene, const ParamSet& params) {
  FrameRequest request;
  request.camera = OrbitCamera::framing(scene.bounds());
  request.width = 64;
  request.height = 64;
  renderer.render(params, request);
}

// Part 2 alone (grading/probe.h): chebyshev_upper_bound on moments and depths chosen so that float32
// computes E[z^2] - E[z]^2 and z - E[z] exactly (means with few mantissa bits, variances and distances
// that are powers of two): any deviation from the CPU bound beyond a few ulps is the formula's.
constexpr double kMeans[] = {0.25, 0.5, 0.625, 0.75, 0.875};
constexpr int kVarianceExponents[] = {-6, -10, -14, -18, -22};  // sigma^2 = 2^e, and 0, and -2^-18
constexpr int kDistanceExponents[] = {-3, -5, -8, -12};           // z - mu = +-2^e, and 0
constexpr float kProbeMinVariances[] = {0x1p-20f, 0x1p-12f};      // u_min_variance, one pass each
constexpr double kBoundTolerance = 1e-5;                           // float32 division: ~1e-7
constexpr double kMaxChebyshevMismatch = 0;                        // cases off by more than that: none

struct ChebyshevCase {
  double mu, m2, z;
  enum Kind { kLitSide, kBound, kClamped } kind;
};

double chebyshev_reference(const ChebyshevCase& c, double min_variance) {
  if (c.z <= c.mu) return 1.0;
  const double variance = std::max(c.m2 - c.mu * c.mu, min_variance);
  const double d = c.z - c.mu;
  return variance / (variance + d * d);
}

void probe_chebyshev(CheckContext& ctx, CheckResult& result) {
  std::vector<double> variances = {0.0, -0x1p-18};
  for (int e : kVarianceExponents) variances.push_back(std::ldexp(1.0, e));
  std::vector<double> distances = {0.0};
  for (int e : kDistanceExponents) {
    distances.push_back(std::ldexp(1.0, e));
    distances.push_back(-std::ldexp(1.0, e));
  }
  std::vector<ChebyshevCase> cases;
  ProbeRequest request;
  request.fragment = "shaders/probe/chebyshev.frag";
  for (double mu : kMeans)
    for (double variance : variances)
      for (double d : distances) {
        const ChebyshevCase c{mu, mu * mu + variance, mu + d,
                              d <= 0 ? ChebyshevCase::kLitSide : ChebyshevCase::kBound};
        cases.push_back(c);
        request.in0.push_back({static_cast<float>(c.mu), static_cast<float>(c.m2), static_cast<float>(c.z), 0.0f});
      }
  for (float min_variance : kProbeMinVariances)
    request.passes.push_back([min_variance](GLuint program) { set_uniform(program, "u_min_variance", min_variance); });
  const auto v = run_probe(ctx.hooks_with_only(1), request);
  // Per kind: the cases whose bound differs from the reference; the clamped ones are those whose
  // variance is below the pass's minimum (where the clamp decides the value).
  double wrong[3] = {0, 0, 0}, total[3] = {0, 0, 0}, worst = 0;
  for (std::size_t pass = 0; pass < v.size(); ++pass) {
    const double min_variance = kProbeMinVariances[pass];
    for (std::size_t i = 0; i < cases.size(); ++i) {
      ChebyshevCase c = cases[i];
      if (c.kind == ChebyshevCase::kBound && c.m2 - c.mu * c.mu < min_variance) c.kind = ChebyshevCase::kClamped;
      const double error = std::abs(static_cast<double>(v[pass][i]) - chebyshev_reference(c, min_variance));
      const bool bad = !(error <= kBoundTolerance);
      wrong[c.kind] += bad;
      total[c.kind] += 1;
      worst = std::max(worst, std::isfinite(error) ? error : 1e30);
    }
  }
  result.metrics["chebyshev_probe"] = {{"cases", total[0] + total[1] + total[2]}, {"lit_side_cases", total[0]},
                                       {"bound_cases", total[1]}, {"clamped_cases", total[2]}, {"worst_error", worst}};
  const std::string why = "probe: exact float32 inputs, the CPU bound within 1e-5";
  result.criteria.push_back({"chebyshev.lit_side_mismatch", wrong[0] / total[0], Criterion::kAtMost, kMaxChebyshevMismatch, why,
                             "in front of the mean (z <= E[z]) the point is fully lit: return 1 there (the one-sided case)."});
  result.criteria.push_back({"chebyshev.bound_mismatch", wrong[1] / total[1], Criterion::kAtMost, kMaxChebyshevMismatch, why,
                             "behind the mean the bound is sigma^2 / (sigma^2 + (z - mu)^2) with sigma^2 = E[z^2] - E[z]^2 "
                             "(a variance, not a standard deviation; the distance squared)."});
  result.criteria.push_back({"chebyshev.min_variance_mismatch", wrong[2] / total[2], Criterion::kAtMost, kMaxChebyshevMismatch, why,
                             "clamp the variance to at least u_min_variance (max, not min): E[z^2] - E[z]^2 can cancel "
                             "to 0 or below in floating point."});
}

void check_vsm_setup(CheckContext& ctx, CheckResult& result) {
  probe_chebyshev(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  // 1. The lit result against the oracle (reported: lab 4 fixes the bias and the bleeding; the bound
  // itself is graded by the probe above).
  const Features hooks = ctx.hooks();
  const auto m = ctx.measure(params, hooks, std::string("lab03_") + impl_name(ctx.impl));
  result.metrics["oracle"] = to_json(m.metrics);
  result.metrics["render_ms"] = m.render_ms;
  result.metrics["oracle_ms"] = m.oracle_ms;

  // 2. The plain depth map of the same light view (32-bit float depth, the same culling), then the moments.
  Renderer& r = ctx.renderer;
  ParamSet depth_params = params;
  depth_params.set_from_string("shadow.depth_format", "32F");
  Features depth_hooks;
  depth_hooks.light_fit = hooks.light_fit;
  depth_hooks.shadow_cull_override = hooks.shadow_cull_override;
  ctx.use(depth_hooks);
  render_for_readback(r, ctx.scene(), depth_params);
  int depth_size = 0;
  const std::vector<float> depth = r.read_shadow_depth(&depth_size);
  ctx.use(hooks);
  render_for_readback(r, ctx.scene(), params);
  int size = 0;
  const std::vector<float> moments = r.read_moments(&size);
  if (size != depth_size) throw std::runtime_error("moments and depth maps differ in size");
  const MomentsComparison c = compare_moments(depth, moments, size);
  const MomentsTargetInfo info = r.moments_targets();
  result.metrics["moments"] = {
      {"size", size},
      {"max_first_moment_error", c.max_first_error},
      {"max_second_moment_error", c.max_second_error},
      {"second_moment_texels_compared", c.second_compared},
      {"second_moment_texels_skipped_at_edges", c.second_skipped},
      {"negative_variance_texels", c.negative_variance},
      {"min_variance", c.min_variance},
      {"background_texels", c.background},
      {"background_texels_not_clear_value", c.background_wrong},
      {"non_finite_texels", c.non_finite},
  };
  result.metrics["targets"] = {{"internal_format", info.internal_format},
                               {"min_filter", info.min_filter},
                               {"mag_filter", info.mag_filter},
                               {"depth_renderbuffer_format", info.depth_internal_format},
                               {"color_attachment_type", info.color_attachment_type},
                               {"depth_attachment_type", info.depth_attachment_type}};
  const bool rg16 = params.get(param::vsm_format) == "RG16F";
  result.criteria.insert(result.criteria.end(), {
      {"moments.non_finite_texels", static_cast<double>(c.non_finite), Criterion::kAtMost, kMaxBadTexels, "no NaN or Inf"},
      {"moments.max_first_moment_error", c.max_first_error, Criterion::kAtMost, rg16 ? kMaxMomentErrorHalfFloat : kMaxFirstMomentError,
       rg16 ? "RG16F: half-float rounding of z in [0, 1]" : "E[z] is the plain depth, to float32 rounding (RG32F)"},
      {"moments.max_second_moment_error", c.max_second_error, Criterion::kAtMost, rg16 ? kMaxMomentErrorHalfFloat : kMaxSecondMomentError,
       "z^2 + slope term from finite differences; float rounding bound (INSTRUCTOR.md)"},
      {"moments.background_texels_not_clear_value", static_cast<double>(c.background_wrong), Criterion::kAtMost, kMaxBadTexels,
       "empty texels hold the clear value (1, 1)"},
  });
  // In half floats z^2 and z*z round differently (11-bit mantissa): negative variances are expected and
  // only reported; the lit pass's minimum variance covers them.
  if (!rg16)
    result.criteria.push_back({"moments.negative_variance_texels", static_cast<double>(c.negative_variance),
                               Criterion::kAtMost, kMaxBadTexels, "sigma^2 = E[z^2] - E[z]^2 never negative"});
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Variance shadow maps: setup";
  lab.summary = "Store the moments (z, z^2) in a filterable RG32F map and light with Chebyshev's bound.";
  lab.exercise_files = {kExerciseMoments, kExerciseChebyshev};
  lab.solution_files = {"shaders/vsm/moments.glsl", "shaders/vsm/chebyshev.glsl"};
  lab.params = specs_of(param::vsm_format, param::vsm_min_variance);
  lab.presets = {
      {"no minimum variance",
       "The smallest clamp: with the slope term in the moments, hardly anything changes.",
       {{"vsm.min_variance", "1e-7"}}},
      {"RG16F",
       "Half floats: z is rounded to 5e-4 and E[z^2] - E[z]^2 goes negative in places (red in the variance quad).",
       {{"vsm.format", "RG16F"}},
       {.provokes = "negative variance", .fixed_by = "RG32F"}, {.camera = kShadowEdgeCamera}},
      {"grazing", "A low light: wide variance on the ground.", {{"light.elevation", "15"}}},
      {"RG32F", "The fix for RG16F: full floats keep E[z^2] - E[z]^2 >= 0.", {{"vsm.format", "RG32F"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.technique = ShadowTechnique::Moments;
    hooks.includes["lab/visibility.glsl"] = kVisibility;
    hooks.includes["lab/moments.glsl"] = files.at(0).string();
    hooks.includes["lab/chebyshev.glsl"] = files.at(1).string();
    return hooks;
  };
  lab.check = check_vsm_setup;
  return lab;
}

}  // namespace shadowlab
