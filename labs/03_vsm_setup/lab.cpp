// Lab 3: variance shadow maps, the setup (the course's tasks 3 and 4, and task 5's slope term).
// Demonstrates: the shadow map as an RG32F colour attachment with linear filtering and a D24 depth
// renderbuffer, cleared to (1, 1, 0, 0); the moments (z, z^2 + slope term) written by the shadow pass;
// Chebyshev's bound with a minimum variance in the lit pass; debug quads of E[z], E[z^2] and sigma^2.
// Check: read-backs of the moments against the plain depth map of the same light view, GL's own
// report of the texture's format and filtering, and the lit result's error against the oracle.
#include "grading/lab.h"

#include <cmath>
#include <cstdio>

#include "labs/03_vsm_setup/gl_setup.h"
#include "grading/check.h"
#include "grading/gl_exercise_check.h"
#include "grading/gl_names.h"
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

// Lab 3's GL exercise (gl_setup.h): the graded gl_moments_target.cpp (the file on disk, a submission's, or
// the solution: the renderer's renderer/moments_target.cpp) is built with its host and run in the sandbox.
constexpr const char* kGlExercise = SHADOWLAB_LAB_FOLDER "/gl_moments_target.cpp";
constexpr const char* kGlSolution = "renderer/moments_target.cpp";
// The lab folder's exercise host (labs/CMakeLists.txt): the folder's name.
const std::string kHost = std::string(SHADOWLAB_LAB_FOLDER).substr(std::string("labs/").size());
// A map size that is no power of two (a size written into the code is found out) in a window larger
// than the map (a viewport left at the window's size is found out).
constexpr MomentsCall kCall{300, 1280, 720};
// State is exact: no texel, pixel, wrong parameter or error is allowed.
constexpr double kNoDifference = 0;
// The fewest bits a moment may have: the course's RG32F (32-bit floats; an 8-bit or half-float moment
// loses the variance, gl_setup.probe_bounds_wrong shows how much).
constexpr int kMomentBits = 32;
// The fewest depth bits a depth format has (GL_DEPTH_COMPONENT16): the depth test needs no more here.
constexpr int kMinDepthBits = 16;

nlohmann::json state_json(const MomentsState& s) {
  nlohmann::json moments = nlohmann::json::array(), bounds = nlohmann::json::array();
  for (int i = 0; i < moments_probe::kGlProbePoints; ++i) {
    moments.push_back({s.probe_moments[i][0], s.probe_moments[i][1]});
    bounds.push_back(s.probe_bounds[i]);
  }
  return {{"gl_error_after_create", gl_enum_name(s.gl_error_after_create)}, {"is_framebuffer", s.is_framebuffer != 0},
          {"is_texture", s.is_texture != 0}, {"is_renderbuffer", s.is_renderbuffer != 0}, {"size", s.size},
          {"status", gl_enum_name(s.status)}, {"colour_attachment_type", gl_enum_name(s.colour_attachment_type)},
          {"colour_attachment_is_the_moments", s.colour_attachment_name == s.texture && s.texture != 0},
          {"depth_attachment_type", gl_enum_name(s.depth_attachment_type)},
          {"depth_attachment_is_the_renderbuffer", s.depth_attachment_name == s.renderbuffer && s.renderbuffer != 0},
          {"depth_bits", s.depth_bits}, {"renderbuffer_format", gl_enum_name(s.renderbuffer_format)},
          {"internal_format", gl_enum_name(s.internal_format)}, {"width", s.width}, {"height", s.height},
          {"red_bits", s.red_bits}, {"green_bits", s.green_bits}, {"red_type", gl_enum_name(s.red_type)},
          {"min_filter", gl_enum_name(s.min_filter)}, {"mag_filter", gl_enum_name(s.mag_filter)},
          {"wrap_s", gl_enum_name(s.wrap_s)}, {"wrap_t", gl_enum_name(s.wrap_t)},
          {"border", {s.border[0], s.border[1], s.border[2], s.border[3]}},
          {"gl_error_after_begin", gl_enum_name(s.gl_error_after_begin)},
          {"pass_binds_the_target", s.pass_framebuffer == s.framebuffer && s.framebuffer != 0},
          {"viewport", {s.viewport[0], s.viewport[1], s.viewport[2], s.viewport[3]}},
          {"moments_off_clear", s.moments_off_clear}, {"depth_min", s.depth_min},
          {"probe_moments", moments}, {"probe_bounds", bounds}};
}

std::string completeness_advice(const MomentsState& s) {
  if (!s.is_framebuffer)
    return "target.framebuffer is no framebuffer: make one with glGenFramebuffers and bind it (glBindFramebuffer) "
           "before attaching to it.";
  switch (s.status) {
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "the framebuffer has no image: attach the moments with glFramebufferTexture2D(GL_FRAMEBUFFER, "
             "GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0).";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "an attachment cannot be drawn into: the moments texture needs storage in a colour format (glTexImage2D "
             "with GL_RG32F) and the renderbuffer storage in a depth format (glRenderbufferStorage with "
             "GL_DEPTH_COMPONENT24), each size x size.";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
      return "the framebuffer draws to a colour attachment it does not have: attach the moments to GL_COLOR_ATTACHMENT0.";
    default:
      return "glCheckFramebufferStatus says " + gl_enum_name(s.status) +
             ": attach the moments texture to GL_COLOR_ATTACHMENT0 and the depth renderbuffer to GL_DEPTH_ATTACHMENT.";
  }
}

// Outside [0, 1] the edge's moments, or a border that is the clear value's (E[z] = E[z^2] = 1: lit).
bool clamps(int wrap, const float* border) {
  return wrap == GL_CLAMP_TO_EDGE || (wrap == GL_CLAMP_TO_BORDER && border[0] >= 1.0f && border[1] >= 1.0f);
}

void add_target_criteria(const MomentsState& s, std::vector<Criterion>& c) {
  const std::string read = "read back after create_moments_target(300) with glGet* (an OpenGL state, not a tolerance)";
  c.push_back({"gl_setup.framebuffer_complete", s.status == GL_FRAMEBUFFER_COMPLETE ? 1.0 : 0.0, Criterion::kAtLeast, 1.0,
               "glCheckFramebufferStatus with target.framebuffer bound: GL_FRAMEBUFFER_COMPLETE", completeness_advice(s)});
  const bool colour = s.colour_attachment_type == GL_TEXTURE && s.colour_attachment_name == s.texture && s.texture != 0;
  c.push_back({"gl_setup.colour_attachment_is_the_moments", colour ? 1.0 : 0.0, Criterion::kAtLeast, 1.0,
               "GL_COLOR_ATTACHMENT0's object is target.moments_texture (glGetFramebufferAttachmentParameteriv)",
               "attach target.moments_texture to GL_COLOR_ATTACHMENT0, not to GL_DEPTH_ATTACHMENT: the moments pass "
               "writes (z, z^2) as a colour, and the lit pass reads them through target.moments_texture."});
  const double short_moments = (s.red_bits < kMomentBits) + (s.green_bits < kMomentBits) + (s.red_type != GL_FLOAT);
  c.push_back({"gl_setup.moments_not_float32", short_moments, Criterion::kAtMost, kNoDifference,
               "GL_TEXTURE_RED_SIZE and _GREEN_SIZE of the moments' level 0 below 32, and GL_TEXTURE_RED_TYPE not GL_FLOAT",
               "store the moments in 32-bit floats: glTexImage2D with the internal format moments_format (GL_RG32F). In "
               "8 bits (GL_RGBA8) or half floats E[z^2] - E[z]^2 loses the variance: a receiver just behind a surface "
               "gets another bound (gl_setup.probe_bounds_wrong)."});
  const bool depth = s.depth_attachment_type == GL_RENDERBUFFER && s.depth_attachment_name == s.renderbuffer && s.renderbuffer != 0;
  c.push_back({"gl_setup.depth_attachment_is_the_renderbuffer", depth ? 1.0 : 0.0, Criterion::kAtLeast, 1.0,
               "GL_DEPTH_ATTACHMENT's object is target.depth_renderbuffer, a renderbuffer",
               "attach target.depth_renderbuffer to GL_DEPTH_ATTACHMENT (glFramebufferRenderbuffer): without a depth "
               "buffer the moments pass has no depth test, and a far surface drawn after a near one overwrites it."});
  c.push_back({"gl_setup.depth_bits", static_cast<double>(s.depth_bits), Criterion::kAtLeast, kMinDepthBits,
               "GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE of the depth attachment; 16 bits is the smallest depth format",
               "give the renderbuffer depth storage: glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size)."});
  const double size_error = std::abs(s.width - kCall.size) + std::abs(s.height - kCall.size) + std::abs(s.size - kCall.size);
  c.push_back({"gl_setup.map_size_error", size_error, Criterion::kAtMost, kNoDifference,
               "texels between the moments' width, height, target.size and the size asked for (300)",
               "make the texture and the renderbuffer size x size, with the size the function is given, and return "
               "it in target.size."});
  const double filters = (s.min_filter != GL_LINEAR) + (s.mag_filter != GL_LINEAR);
  c.push_back({"gl_setup.filters_not_linear", filters, Criterion::kAtMost, kNoDifference, read,
               "GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER must both be GL_LINEAR: the mean of two texels' moments "
               "is the moments of both surfaces, which is what VSM filters (nearest reads one texel, a hard edge; the "
               "default minification filter uses mipmaps the map does not have, and reads nothing)."});
  const double wraps = !clamps(s.wrap_s, s.border) + !clamps(s.wrap_t, s.border);
  c.push_back({"gl_setup.wraps_not_clamped", wraps, Criterion::kAtMost, kNoDifference, read,
               "GL_TEXTURE_WRAP_S and _T must be GL_CLAMP_TO_EDGE, or GL_CLAMP_TO_BORDER with a border of (1, 1, 0, 0): "
               "with GL_REPEAT (the default) a point beyond the map's edge reads the other side of the map, and a "
               "shadow from there appears where nothing casts one."});
}

GlPassState pass_state(const MomentsState& s) {
  return {"create_moments_target", "begin_moments_pass", "moments pass", s.framebuffer, s.pass_framebuffer, s.viewport,
          kCall.size, kCall.window_width, kCall.window_height, s.gl_error_after_create, s.gl_error_after_begin};
}

void add_pass_criteria(const MomentsState& s, std::vector<Criterion>& c) {
  add_pass_binding_criteria(pass_state(s), c);
  c.push_back({"gl_setup.moments_not_cleared", s.moments_off_clear < 0.0f ? 1.0 : s.moments_off_clear, Criterion::kAtMost,
               kNoDifference, "the largest |E[z] - 1| and |E[z^2] - 1| in the map after begin_moments_pass; it held (0.25, 0.0625) before",
               "clear the moments to (1, 1, 0, 0) in begin_moments_pass: glClearColor(1, 1, 0, 0) then glClear with "
               "GL_COLOR_BUFFER_BIT, with the target bound. Empty texels then hold the far plane's moments and light "
               "every point; cleared to 0 they read as an occluder at depth 0 and shadow everything."});
  const double uncleared = s.depth_min < 0.0f ? 1.0 : 1.0 - s.depth_min;
  c.push_back({"gl_setup.depth_below_far_after_clear", uncleared, Criterion::kAtMost, kNoDifference,
               "1 - the smallest depth in the depth buffer after begin_moments_pass; it held 0.25 before (a last frame's)",
               "clear the depth too (GL_DEPTH_BUFFER_BIT in the same glClear, clear depth 1): otherwise last frame's "
               "depths fail this frame's surfaces in the depth test, and their moments are never written."});
}

void add_probe_criteria(const MomentsState& s, std::vector<Criterion>& c) {
  // The moments each probe point must read (gl_setup.h): the near occluder's, the clear value's, the clear
  // value's beyond the right edge, the far occluder's beyond the top, the mean of the near occluder's and
  // the clear value's on its edge; the bound for its receiver, as the lab's Chebyshev probe computes it.
  using namespace moments_probe;
  const double near = kNearDepth, far = kFarDepth;
  const double right_moments[kGlProbePoints][2] = {{near, near * near}, {1, 1}, {1, 1}, {far, far * far},
                                                   {(near + 1) / 2, (near * near + 1) / 2}};
  double wrong = 0;
  for (int i = 0; i < kGlProbePoints; ++i) {
    const ChebyshevCase expected{right_moments[i][0], right_moments[i][1], kReceiverDepth[i], ChebyshevCase::kBound};
    wrong += !(std::abs(s.probe_bounds[i] - chebyshev_reference(expected, kProbeMinVariance)) <= kBoundTolerance);
  }
  c.push_back({"gl_setup.probe_bounds_wrong", wrong, Criterion::kAtMost, kNoDifference,
               "the moments of an occluder at depth 0.3 over the map's lower left quarter and of one at 0.7 over its left "
               "half, drawn through begin_moments_pass's state; then Chebyshev's bound read with texture() at 5 points, "
               "within 1e-5 of the CPU's (probe_moments, probe_bounds in the metrics)",
               "what the lit pass would compute is wrong at some of the 5 points (0.02 behind the near occluder 0.2; in "
               "the open and beyond the right and top edges 1; on the near occluder's edge 0.845, filtered): the "
               "criteria above say which setting shows (8-bit moments 0.02 behind, no depth buffer the far occluder "
               "over the near one, nearest filtering 0 or 1 on the edge, a repeating map or a clear to 0 a shadow in "
               "the open)."});
  c.push_back(gl_errors_criterion(pass_state(s)));
}

// The GL exercise graded: the file built and run in the sandbox with its own headless OpenGL context, the
// state it left turned into the gl_setup.* criteria.
void check_gl_setup(CheckContext& ctx, CheckResult& result) {
  const auto program = build_gl_exercise(
      ctx, result,
      {kGlExercise, kGlSolution, kHost, {SHADOWLAB_LAB_FOLDER "/gl_setup.h", "renderer/moments_target.h", "renderer/gl.h"},
       "lab 3's OpenGL part"});
  if (!program) return;
  const MomentsState state = program->call<MomentsState>(kCall);
  result.metrics["gl_setup"] = state_json(state);
  add_target_criteria(state, result.criteria);
  add_pass_criteria(state, result.criteria);
  add_probe_criteria(state, result.criteria);
}

void check_vsm_setup(CheckContext& ctx, CheckResult& result) {
  check_gl_setup(ctx, result);
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
  lab.gl_exercise_files = {kGlExercise};
  lab.gl_solution_files = {kGlSolution};
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
