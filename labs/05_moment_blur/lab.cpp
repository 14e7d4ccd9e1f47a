// Lab 5: a separable Gaussian blur of the moments (the course's task 6).
// Demonstrates: blurring the moments rather than the lighting, two passes (X, then Y) with their own
// shaders through a ping-pong texture, radius and sigma sliders, and that radius 0 costs nothing.
// Check: the GPU's blurred moments against a CPU Gaussian (normalised weights, clamp to edge) for radii
// 1, 2, 4, 8, 16 at sigma = r / 2 and three held-out (radius, sigma) pairs; reported: at radius 0 no
// blur pass runs and no blur target exists (the renderer's doing, tested in BlurTest); per-pass time and the
// oracle's edge error by radius are reported.
// The OpenGL part (gl_blur_passes.cpp: the ping-pong target and the two passes, solution
// renderer/blur_passes.cpp) is built and run in the sandbox first: the gl_blur.* criteria.
#include "grading/lab.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <random>

#include "labs/05_moment_blur/gl_setup.h"
#include "grading/check.h"
#include "grading/gl_exercise_check.h"
#include "grading/cpp_exercise.h"
#include "labs/vsm_features.h"
#include "renderer/gl_objects.h"
#include "renderer/moments_pass.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/vsm/gaussian_blur.glsl";  // the renderer's own blur

// The bound per texel. Float32 sums of at most 33 weighted values in [0, 1], twice, are off by
// about 33 * 2^-24 = 2e-6 at worst; a kernel that is not normalised, not clamped at the edge or one
// texel off is off by 1e-3 and more near every depth edge.
constexpr double kMaxTexelError = 1e-4;
constexpr int kRadii[] = {1, 2, 4, 8, 16};
// Held-out (radius, sigma) pairs: radius 1..8, sigma from 0.3 to 1.5 times the radius.
constexpr int kHeldOutCases = 3;
constexpr int kMaxHeldOutRadius = 8;
constexpr double kHeldOutSigmaPerRadius[2] = {0.3, 1.5};
constexpr double kMaxSigma = 8.0;  // the slider's range
// Repeats of the blurred frame for its GPU time (the median is reported).
// (`shadowlab bench` measures the blur's cost properly; the check reports one frame's time.)
constexpr int kTimingRepeats = 1;

// Sigma for a radius in the check: the kernel spans +-2 sigma, the usual cut-off (weights at the end
// are e^-2 = 0.14 of the centre).
double check_sigma(int radius) { return 0.5 * radius; }

// The reference: the same separable Gaussian in double precision, X then Y, clamped to the edge
// (cpu_gaussian_blur in renderer/moments_pass.h, shared with the blur tests and benchmark).

double pass_ms(const FrameStats& stats, const std::string& name) {
  for (const auto& p : stats.passes)
    if (p.name == name) return p.gpu_ms;
  return -1.0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// 1. The lit result at the lab's settings, and the oracle's edge error by radius (reported).
nlohmann::json oracle_by_radius(CheckContext& ctx, const ParamSet& params, const Features& hooks) {
  nlohmann::json by_radius = nlohmann::json::array();
  const auto out_dir = ctx.out_dir;
  for (int radius : {0, 1, 2, 4, 8, 16}) {
    ParamSet p = params;
    p.set("vsm.blur_radius", radius);
    if (radius > 0) p.set("vsm.blur_sigma", check_sigma(radius));
    ctx.out_dir = radius == 0 || radius == 4 ? out_dir : std::filesystem::path{};
    const auto m = ctx.measure(p, hooks, "lab05_radius" + std::to_string(radius) + "_" + impl_name(ctx.impl));
    by_radius.push_back({{"radius", radius},
                         {"sigma", radius > 0 ? check_sigma(radius) : 0.0},
                         {"mae_edge", m.metrics.mae_edge},
                         {"mae_interior", m.metrics.mae_interior},
                         {"acne_rate_all", m.metrics.acne_rate_all},
                         {"leak_rate_all", m.metrics.leak_rate_all},
                         {"bleeding_rate", m.metrics.bleeding_rate}});
  }
  ctx.out_dir = out_dir;
  return by_radius;
}

// The radii with sigma = r / 2, then held-out (radius, sigma) pairs the lab's text does not fix, so
// that a kernel which ignores one of the two sliders cannot pass.
std::vector<std::pair<int, double>> blur_cases(CheckContext& ctx, CheckResult& result) {
  std::vector<std::pair<int, double>> cases;
  for (int radius : kRadii) cases.push_back({radius, check_sigma(radius)});
  std::mt19937 rng = ctx.held_out_rng();
  for (int i = 0; i < kHeldOutCases; ++i) {
    const int radius = std::uniform_int_distribution<int>(1, kMaxHeldOutRadius)(rng);
    const double sigma = std::min(kMaxSigma, radius * std::uniform_real_distribution<double>(kHeldOutSigmaPerRadius[0],
                                                                                              kHeldOutSigmaPerRadius[1])(rng));
    cases.push_back({radius, sigma});
    result.conditions.push_back({{"tag", "held_out_" + std::to_string(i + 1)}, {"blur_radius", radius}, {"blur_sigma", sigma}});
  }
  return cases;
}

// The largest |gpu - cpu| over the texels (1e30 once a texel is not finite), counting those.
double max_texel_error(const std::vector<float>& gpu, const std::vector<double>& cpu, std::size_t* non_finite_out) {
  double max_error = 0.0;
  std::size_t non_finite = 0;
  for (std::size_t i = 0; i < gpu.size(); ++i) {
    if (!std::isfinite(gpu[i])) {
      ++non_finite;
      max_error = 1e30;
      continue;
    }
    max_error = std::max(max_error, std::abs(static_cast<double>(gpu[i]) - cpu[i]));
  }
  *non_finite_out = non_finite;
  return max_error;
}


// Lab 5's GL exercise (gl_setup.h): the graded gl_blur_passes.cpp (the file on disk, a submission's, or
// the solution: the renderer's renderer/blur_passes.cpp) is built with its host and run in the sandbox.
constexpr const char* kGlExercise = SHADOWLAB_LAB_FOLDER "/gl_blur_passes.cpp";
constexpr const char* kGlSolution = "renderer/blur_passes.cpp";
// The lab folder's exercise host (labs/CMakeLists.txt): the folder's name.
const std::string kHost = std::string(SHADOWLAB_LAB_FOLDER).substr(std::string("labs/").size());
// A map of 24 texels (no power of two) and a window smaller than it, as a 1280 x 720 window is than a
// 2048 map: a viewport left at the window's size leaves the map's far side unblurred (a larger window
// would not show in the texels: the full-screen triangle covers the map and the shaders read
// gl_FragCoord). Blurred with radius 3 and sigma 1.5 (lab 5's sigma = r / 2).
constexpr BlurCall kGlCall{24, 15, 9, 3, 1.5f};
static_assert(kGlCall.size <= kBlurMaxSize, "the host's replies hold every texel");
// State is exact: no wrong binding, parameter, pass or error is allowed.
constexpr double kNoDifference = 0;
// u_texel_size times the size must be 1: float32 rounds 1 / 24 to within 2^-24 = 6e-8 of it; 1 / (size - 1)
// is 4 % off, a texel size in texels (1) 2300 %.
constexpr double kMaxTexelSizeError = 1e-6;

std::string gl_name(int value) {
  static const std::map<int, std::string> names = {
      {GL_NONE, "GL_NONE"}, {GL_NEAREST, "GL_NEAREST"}, {GL_LINEAR, "GL_LINEAR"},
      {GL_NEAREST_MIPMAP_LINEAR, "GL_NEAREST_MIPMAP_LINEAR"}, {GL_LINEAR_MIPMAP_LINEAR, "GL_LINEAR_MIPMAP_LINEAR"},
      {GL_REPEAT, "GL_REPEAT"}, {GL_CLAMP_TO_EDGE, "GL_CLAMP_TO_EDGE"}, {GL_CLAMP_TO_BORDER, "GL_CLAMP_TO_BORDER"},
      {GL_MIRRORED_REPEAT, "GL_MIRRORED_REPEAT"}, {GL_TEXTURE, "GL_TEXTURE"}, {GL_FLOAT, "GL_FLOAT"},
      {GL_UNSIGNED_NORMALIZED, "GL_UNSIGNED_NORMALIZED"}, {GL_FRAMEBUFFER_COMPLETE, "GL_FRAMEBUFFER_COMPLETE"},
      {GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"},
      {GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"},
      {GL_RG32F, "GL_RG32F"}, {GL_RGBA32F, "GL_RGBA32F"}, {GL_RG16F, "GL_RG16F"}, {GL_RGBA16F, "GL_RGBA16F"},
      {GL_RGBA8, "GL_RGBA8"}, {GL_RG8, "GL_RG8"}, {GL_INVALID_ENUM, "GL_INVALID_ENUM"},
      {GL_INVALID_VALUE, "GL_INVALID_VALUE"}, {GL_INVALID_OPERATION, "GL_INVALID_OPERATION"},
      {GL_INVALID_FRAMEBUFFER_OPERATION, "GL_INVALID_FRAMEBUFFER_OPERATION"}, {GL_OUT_OF_MEMORY, "GL_OUT_OF_MEMORY"}};
  const auto found = names.find(value);
  if (found != names.end()) return found->second;
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(value));
  return hex;
}

// What the texture names of a draw are, in the lab's words.
std::string texture_role(const BlurState& s, int name) {
  if (name == 0) return "none";
  if (name == s.moments_texture) return "moments";
  if (name == s.texture) return "target";
  return "other";
}

nlohmann::json gl_state_json(const BlurState& s) {
  nlohmann::json draws = nlohmann::json::array();
  for (int i = 0; i < std::min(s.draws, kBlurMaxDraws); ++i) {
    const BlurDraw& d = s.draw[i];
    draws.push_back({{"pass", d.pass}, {"reads", texture_role(s, d.reads)}, {"writes", texture_role(s, d.writes)},
                     {"program", d.program == s.program_x ? "program_x" : d.program == s.program_y ? "program_y" : "other"},
                     {"viewport", {d.viewport[0], d.viewport[1], d.viewport[2], d.viewport[3]}},
                     {"depth_test", d.depth_test != 0}, {"unit", d.unit},
                     {"direction", {d.direction[0], d.direction[1]}}, {"texel_size", {d.texel_size[0], d.texel_size[1]}}});
  }
  return {{"gl_error_after_create", gl_name(s.gl_error_after_create)}, {"is_framebuffer", s.is_framebuffer != 0},
          {"is_texture", s.is_texture != 0}, {"size", s.size}, {"status", gl_name(s.status)},
          {"colour_attachment_is_the_texture", s.colour_attachment_type == GL_TEXTURE && s.colour_attachment_name == s.texture},
          {"internal_format", gl_name(s.internal_format)}, {"width", s.width}, {"height", s.height},
          {"red_type", gl_name(s.red_type)}, {"red_bits", s.red_bits}, {"min_filter", gl_name(s.min_filter)},
          {"mag_filter", gl_name(s.mag_filter)}, {"wrap_s", gl_name(s.wrap_s)}, {"wrap_t", gl_name(s.wrap_t)},
          {"gl_error_after_run", gl_name(s.gl_error_after_run)}, {"draws", s.draws}, {"passes", draws}};
}

// The ping-pong target's criteria (after create_blur_target).
void add_target_criteria(const BlurState& s, CheckResult& result) {
  auto& c = result.criteria;
  const std::string read = "read back after create_blur_target(24, GL_RG32F) with glGet* (an OpenGL state, not a tolerance)";
  const bool attached = s.colour_attachment_type == GL_TEXTURE && s.colour_attachment_name == s.texture && s.texture != 0;
  c.push_back({"gl_blur.target_complete", s.status == GL_FRAMEBUFFER_COMPLETE && attached ? 1.0 : 0.0, Criterion::kAtLeast,
               1.0, "glCheckFramebufferStatus with target.framebuffer bound is GL_FRAMEBUFFER_COMPLETE, and its "
               "GL_COLOR_ATTACHMENT0 is target.texture",
               "make a framebuffer (glGenFramebuffers, glBindFramebuffer) and attach target.texture as its colour "
               "attachment 0 (glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0))."});
  c.push_back({"gl_blur.target_not_float32", s.red_type == GL_FLOAT && s.red_bits == 32 ? 0.0 : 1.0, Criterion::kAtMost,
               kNoDifference, "GL_TEXTURE_RED_TYPE and _SIZE of the target's level 0: GL_FLOAT, 32 bits, as the moments",
               "give the target the moments' own format (the internal_format argument, GL_RG32F): an 8-bit texture "
               "(GL_RGBA8) stores the moments in steps of 1/255 and clamps them to [0, 1], a 16-bit float one "
               "rounds E[z^2] to 11 bits, and the variance E[z^2] - E[z]^2 is lost to either."});
  const double size_error = std::abs(s.width - kGlCall.size) + std::abs(s.height - kGlCall.size) + std::abs(s.size - kGlCall.size);
  c.push_back({"gl_blur.target_size_error", size_error, Criterion::kAtMost, kNoDifference,
               "texels between the target's width, height, target.size and the size asked for (24)",
               "make the texture size x size, the moments' size, and return it in target.size."});
  const bool mipmapped = s.min_filter != GL_NEAREST && s.min_filter != GL_LINEAR;
  c.push_back({"gl_blur.target_min_filter_needs_mipmaps", mipmapped ? 1.0 : 0.0, Criterion::kAtMost, kNoDifference, read,
               "set GL_TEXTURE_MIN_FILTER to GL_LINEAR (or GL_NEAREST): the default, GL_NEAREST_MIPMAP_LINEAR, reads "
               "mipmaps the target does not have, so the texture is incomplete and every read returns 0."});
  const double wraps = (s.wrap_s != GL_CLAMP_TO_EDGE) + (s.wrap_t != GL_CLAMP_TO_EDGE);
  c.push_back({"gl_blur.target_wraps_not_clamped", wraps, Criterion::kAtMost, kNoDifference, read,
               "GL_TEXTURE_WRAP_S and _T must be GL_CLAMP_TO_EDGE: a tap beyond the edge then reads the edge texel, as "
               "the blur's clamp to edge does; with GL_REPEAT (the default) it reads the other side of the map, and "
               "shadows bleed in from the opposite edge."});
}

// The passes' criteria (the state recorded at each job.draw, then the texels).
void add_pass_criteria(const BlurState& s, CheckResult& result) {
  auto& c = result.criteria;
  const int n = std::min(s.draws, kBlurMaxDraws);
  c.push_back({"gl_blur.pass_count_error", std::abs(s.draws - 2.0), Criterion::kAtMost, kNoDifference,
               "job.draw calls in run_blur_passes: the separable blur is two passes",
               "draw twice: the X pass (u_direction (1, 0)), then the Y pass ((0, 1)); one pass blurs in one direction "
               "only, and shadows' edges stay hard across it."});
  double directions = 0, programs = 0, texel = 0, viewport = 0, depth = 0, loops = 0;
  bool x_seen = false, y_seen = false;
  for (int i = 0; i < n; ++i) {
    const BlurDraw& d = s.draw[i];
    const bool x = d.direction[0] == 1.0f && d.direction[1] == 0.0f, y = d.direction[0] == 0.0f && d.direction[1] == 1.0f;
    directions += (!x && !y) || (x && x_seen) || (y && y_seen);
    x_seen = x_seen || x;
    y_seen = y_seen || y;
    programs += (x && d.program != s.program_x) || (y && d.program != s.program_y);
    for (float t : d.texel_size) texel = std::max(texel, std::abs(t * kGlCall.size - 1.0));
    viewport += std::abs(d.viewport[0]) + std::abs(d.viewport[1]) + std::abs(d.viewport[2] - kGlCall.size) +
                std::abs(d.viewport[3] - kGlCall.size);
    depth += d.depth_test != 0;
    loops += d.reads != 0 && d.reads == d.writes;
  }
  const std::string at_draw = "read with glGet* at each job.draw (passes in the metrics)";
  c.push_back({"gl_blur.pass_directions_wrong", directions, Criterion::kAtMost, kNoDifference, at_draw + ": u_direction",
               "set u_direction to (1, 0) for one pass and (0, 1) for the other, in texels: two passes in the same "
               "direction blur one axis twice and the other not at all."});
  c.push_back({"gl_blur.pass_programs_wrong", programs, Criterion::kAtMost, kNoDifference, at_draw + ": GL_CURRENT_PROGRAM",
               "use job.program_x for the X pass and job.program_y for the Y pass (glUseProgram before setting their "
               "uniforms): the renderer's programs have their direction compiled in and ignore u_direction."});
  c.push_back({"gl_blur.texel_size_error", texel, Criterion::kAtMost, kMaxTexelSizeError,
               at_draw + ": |u_texel_size x 24 - 1|; float32 rounds 1/24 within 6e-8",
               "u_texel_size is one texel in texture coordinates, 1 / size (not 1 / (size - 1), not 1: the taps are "
               "texel + i * direction, and coordinates run from 0 to 1 over size texels)."});
  c.push_back({"gl_blur.viewport_error", viewport, Criterion::kAtMost, kNoDifference,
               at_draw + ": pixels between GL_VIEWPORT and (0, 0, 24, 24); it was the window's 15 x 9",
               "glViewport(0, 0, size, size) before the passes: the viewport is not part of the framebuffer, and the "
               "window's covers only its lower left 15 x 9 texels of the map's 24 x 24, and the rest keeps unblurred moments."});
  c.push_back({"gl_blur.depth_test_on", depth, Criterion::kAtMost, kNoDifference, at_draw + ": glIsEnabled(GL_DEPTH_TEST)",
               "glDisable(GL_DEPTH_TEST) before the passes: the moments framebuffer keeps the moments pass's depth "
               "buffer, and the full-screen triangle at depth 0.5 is discarded wherever a caster is nearer (the "
               "target has no depth buffer, where a depth test passes everything)."});
  c.push_back({"gl_blur.feedback_loops", loops, Criterion::kAtMost, kNoDifference,
               at_draw + ": a pass whose source texture (the unit u_moments names) is its framebuffer's colour attachment",
               "never read the texture a pass writes (OpenGL 3.3, section 4.4.3: a feedback loop, undefined): read the "
               "moments into the target, then the target into the moments."});
}

// Which textures the passes read and wrote, and the blurred texels against the CPU's Gaussian.
void add_result_criteria(const BlurState& s, CheckResult& result) {
  auto& c = result.criteria;
  // Pass 1 reads the moments into the target, pass 2 the target back into the moments.
  const int n = std::min(s.draws, kBlurMaxDraws);
  double chain = 4;
  if (n >= 1) chain -= (s.draw[0].reads == s.moments_texture) + (s.draw[0].writes == s.texture && s.texture != 0);
  if (n >= 2) chain -= (s.draw[1].reads == s.texture && s.texture != 0) + (s.draw[1].writes == s.moments_texture);
  c.push_back({"gl_blur.pass_textures_wrong", chain, Criterion::kAtMost, kNoDifference,
               "of the 4 roles (pass 1 reads the moments and writes the target, pass 2 reads the target and writes "
               "the moments), those the first two draws did not fill (reads and writes per pass in the metrics)",
               "bind the texture each pass reads on the unit u_moments names (glActiveTexture, glBindTexture) and the "
               "framebuffer it writes (glBindFramebuffer): X reads job.moments_texture into job.target.framebuffer, Y "
               "reads job.target.texture into job.moments_framebuffer, where the lit pass reads the result."});
  std::vector<float> raw;
  for (int y = 0; y < kGlCall.size; ++y)
    for (int x = 0; x < kGlCall.size; ++x)
      for (int ch = 0; ch < 2; ++ch) raw.push_back(blur_input(kGlCall.size, x, y, ch));
  const std::vector<double> cpu = cpu_gaussian_blur(raw, kGlCall.size, kGlCall.radius, kGlCall.sigma);
  const std::size_t count = cpu.size();
  std::size_t non_finite = 0;
  const double moments_error = max_texel_error({s.moments, s.moments + count}, cpu, &non_finite);
  result.metrics["gl_blur"]["moments_max_texel_error"] = moments_error;
  result.metrics["gl_blur"]["target_max_texel_error"] = 
      s.intermediate[0] < -1e29f ? -1.0 : max_texel_error({s.intermediate, s.intermediate + count}, cpu, &non_finite);
  c.push_back({"gl_blur.result_texel_error", moments_error, Criterion::kAtMost, kMaxTexelError,
               "the moments texture after run_blur_passes against the CPU's separable Gaussian (radius 3, sigma 1.5, "
               "clamp to edge) of an impulse and steps in x and y; float32 sums stay below 2e-6",
               "the blurred moments must end in job.moments_texture, where the lit pass reads them (target_max_texel_error "
               "in the metrics is 0 when they were left in the target); the criteria above say which state is wrong."});
  const double errors = (s.gl_error_after_create != GL_NO_ERROR) + (s.gl_error_after_run != GL_NO_ERROR);
  c.push_back({"gl_blur.gl_errors", errors, Criterion::kAtMost, kNoDifference,
               "glGetError after create_blur_target and during run_blur_passes",
               "a call failed (gl_error_after_create and _run in the metrics): check each call's arguments against "
               "the OpenGL 3.3 reference."});
}

// The GL exercise graded: the file built and run in the sandbox with its own headless OpenGL context, the
// state it left and the texels it produced turned into the gl_blur.* criteria.
void check_gl_blur(CheckContext& ctx, CheckResult& result) {
  const auto program = build_gl_exercise(
      ctx, result,
      {kGlExercise, kGlSolution, kHost, {SHADOWLAB_LAB_FOLDER "/gl_setup.h", "renderer/blur_passes.h", "renderer/gl.h"},
       "lab 5's OpenGL part", "gl_blur"});
  if (!program) return;
  const BlurState state = program->call<BlurState>(kGlCall);
  result.metrics["gl_blur"] = gl_state_json(state);
  add_target_criteria(state, result);
  add_pass_criteria(state, result);
  add_result_criteria(state, result);
}

void check_moment_blur(CheckContext& ctx, CheckResult& result) {
  check_gl_blur(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const Features hooks = ctx.hooks();
  Renderer& r = ctx.renderer;

  result.metrics["oracle_by_radius"] = oracle_by_radius(ctx, params, hooks);

  // 2. Radius 0: no blur pass runs, no blur target is allocated (the renderer's counters and GL's count).
  FrameRequest request;
  request.camera = OrbitCamera::framing(ctx.scene().bounds());
  request.width = 64;
  request.height = 64;
  ParamSet p0 = params;
  p0.set("vsm.blur_radius", 0);
  ctx.use(hooks);
  const long blur_before = r.stats().blur_passes;
  r.render(p0, request);
  const long blur_at_zero = r.stats().blur_passes - blur_before;
  const int textures_at_zero = live_gl_objects(GlKind::Texture);
  const bool target_at_zero = r.moments_targets().blur_target;
  int n = 0;
  const std::vector<float> raw = r.read_moments(&n);

  // 3. Each radius: the GPU's blurred moments against the CPU reference, and the passes' GPU time.
  nlohmann::json radii = nlohmann::json::array();
  double worst = 0.0;
  long blur_passes_run = 0;
  int extra_textures = 0;
  const std::vector<std::pair<int, double>> cases = blur_cases(ctx, result);
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto [radius, sigma] = cases[k];
    const std::string tag = k < std::size(kRadii) ? "radius" + std::to_string(radius)
                                                   : "held_out_" + std::to_string(k - std::size(kRadii) + 1);
    ParamSet p = params;
    p.set("vsm.blur_radius", radius);
    p.set("vsm.blur_sigma", sigma);
    std::vector<double> ms_x, ms_y;
    for (int k = 0; k < kTimingRepeats; ++k) {
      ctx.use(hooks);  // forces the passes to run again
      const long before = r.stats().blur_passes;
      r.render(p, request);
      blur_passes_run += r.stats().blur_passes - before;
      ms_x.push_back(pass_ms(r.stats(), "blur_x"));
      ms_y.push_back(pass_ms(r.stats(), "blur_y"));
    }
    extra_textures = std::max(extra_textures, live_gl_objects(GlKind::Texture) - textures_at_zero);
    int size = 0;
    const std::vector<float> gpu = r.read_moments(&size);
    const std::vector<double> cpu = cpu_gaussian_blur(raw, n, radius, sigma);
    std::size_t non_finite = 0;
    const double max_error = max_texel_error(gpu, cpu, &non_finite);
    worst = std::max(worst, max_error);
    radii.push_back({{"case", tag},
                     {"radius", radius},
                     {"sigma", sigma},
                     {"max_texel_error", max_error},
                     {"non_finite", non_finite},
                     {"gpu_ms_blur_x", median(ms_x)},
                     {"gpu_ms_blur_y", median(ms_y)}});
    result.criteria.push_back({tag + ".max_texel_error", max_error, Criterion::kAtMost, kMaxTexelError,
                               "CPU Gaussian, normalised, clamp to edge; float32 sums stay below 2e-6",
                               "average the 2r + 1 texels with weights exp(-i^2 / (2 sigma^2)) divided by their sum, r and "
                               "sigma from the sliders (u_blur_radius, u_blur_sigma), coordinates clamped to the edge."});
  }
  result.metrics["blur"] = {{"map_size", n}, {"format", params.get(param::vsm_format)}, {"radii", radii}};
  result.metrics["radius0"] = {
      {"blur_passes", blur_at_zero}, {"blur_target", target_at_zero}, {"extra_textures_when_blurring", extra_textures}};
  // Reported, not graded: the renderer, not the student's blur function, decides how many passes run
  // and which targets exist (its own tests hold these: BlurTest.*, SkipTest.*).
  result.metrics["blur"]["passes_per_blurred_map"] =
      static_cast<double>(blur_passes_run) / (static_cast<double>(cases.size()) * kTimingRepeats);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "VSM: Gaussian blur of the moments";
  lab.summary = "Blur the moments in two separable passes (X, then Y) for soft, alias-free shadow edges.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.gl_exercise_files = {kGlExercise};
  lab.gl_solution_files = {kGlSolution};
  lab.params = specs_of(param::vsm_format, param::vsm_min_variance, param::vsm_bleed_delta, param::vsm_blur_radius,
                        param::vsm_blur_sigma, param::vsm_match_light, param::vsm_match_distance);
  for (auto& spec : lab.params) {
    if (spec.key == "vsm.blur_radius") spec.default_value = 4.0;
    if (spec.key == "vsm.blur_sigma") spec.default_value = 2.0;
  }
  for (const auto& spec : vsm_lab_bias_params()) lab.params.push_back(spec);
  lab.presets = {
      {"no blur", "Radius 0: no blur pass runs; edges show the map's texels.", {{"vsm.blur_radius", "0"}},
       {.provokes = "aliasing", .fixed_by = "tuned"}, {.camera = kShadowEdgeCamera}},
      {"soft",
       "Radius 8, sigma 4: wide penumbrae, on lab 4's stacked occluders (lab 4's cut, still on, removes the bleeding there).",
       {{"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}},
       {.provokes = "wide penumbrae", .fixed_by = "tuned"}, {.scene = kStackedOccludersScene, .camera = kStackedOccludersCamera}},
      {"cut-off kernel",
       "Radius 6 with sigma 8: a box filter in disguise, wider than tuned's kernel so that its flat ramps show.",
       {{"vsm.blur_radius", "6"}, {"vsm.blur_sigma", "8"}},
       {.provokes = "box-filter edges", .fixed_by = "tuned"}, {.camera = kShadowEdgeCamera}},
      {"tuned", "The lab's defaults, radius 4 and sigma 2: soft edges, little bleeding.",
       {{"vsm.blur_radius", "4"}, {"vsm.blur_sigma", "2"}}},
      {"matched to the sun",
       "A sun 3 degrees wide and a blur as wide as the penumbra 1 unit under a blocker (radius and sigma follow).",
       {{"light.size", "3"}, {"vsm.match_light", "true"}, {"vsm.match_distance", "1"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.technique = ShadowTechnique::Moments;
    hooks.includes["lab/blur.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_moment_blur;
  // Against a sun with a size: the blur matched to it (at size 0 the lab's radius 4, sigma 2).
  lab.bench.push_back({"vsm matched", "VSM", {{"vsm.match_light", "true"}}, true, false});
  return lab;
}

}  // namespace shadowlab
