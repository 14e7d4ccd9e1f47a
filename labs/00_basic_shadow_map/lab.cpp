// Lab 0: the basic shadow map, the starting point before the numbered exercises.
// Demonstrates: a depth-only pass from the light, the [-1,1] -> [0,1] bias matrix, one depth comparison
// per fragment with a constant bias, and the debug quad showing the shadow map.
// Check: the default scene under the default light (azimuth 35, elevation 50) at the renderer's fixed
// bias 0.005, then three held-out lights, map sizes and scenes: the continuous acne and leak errors over
// interior pixels within lab 1's bounds in every case.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "labs/00_basic_shadow_map/gl_setup.h"
#include "grading/check.h"
#include "grading/cpp_exercise.h"
#include "grading/lab.h"
#include "grading/probe.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = SHADOWLAB_LAB_FOLDER "/solution.glsl";

// Held-out lights stay above 30 degrees, and use lab 1's slope-scaled bias (2 texels x tan, over the
// constant): the lab's constant alone leaves acne on surfaces the light grazes at other lights and map
// sizes, which is lab 1's lesson, not this one's (the bias matrix).
constexpr double kHeldOutSlopeBias = 2.0;
const std::vector<HeldOutRange> kHeldOut = {{30.0f, 50.0f, {"512", "1024", "2048"}, {"default", "stacked"}},
                                            {50.0f, 70.0f, {"512", "1024", "2048"}, {"default", "stacked"}},
                                            {70.0f, 88.0f, {"512", "1024", "2048"}, {"default", "stacked"}}};

constexpr const char* kAdvice =
    "map the light's clip coordinates from [-1, 1] to [0, 1] (x, y and z) before reading the map and comparing.";
const HardLimits kLimits{.lit_advice = kAdvice, .shadow_advice = kAdvice};

// The shadow test alone (grading/probe.h): a light whose clip space is world space, a 64 x 64 map of
// random depths, and points inside and outside the map; each must read the texel it falls in.
constexpr int kProbeMapSize = 64;
constexpr int kProbePoints = 3000;
constexpr float kProbeBias = 0.005f;
// Points are kept this far from texel borders and from the compared depth, where rounding may decide.
constexpr float kBorderMargin = 0.05f;
constexpr float kDepthMargin = 1e-3f;
// The probe grades the lookup (the bias matrix, the texel), not the bias's value: no point lies less
// than this above its texel's stored depth, so any bias from 0 to this decides nothing here. It covers
// the slider's 0.005, the lab sheet's hard-coded `closestDepth + 0.01 > z` (course seed 003) and the
// peter-panning preset's 0.05; the pictures grade the bias.
constexpr float kProbeBiasBand = 0.05f;
// The share of probe points that may disagree with the reference: none should; a few for rounding.
constexpr double kMaxProbeMismatch = 0.002;

void probe_shadow_test(CheckContext& ctx, CheckResult& result) {
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> depths(kProbeMapSize * kProbeMapSize);
  for (auto& d : depths) d = unit(rng) < 0.5f ? 0.3f : 0.7f;
  ProbeRequest request;
  request.fragment = "shaders/probe/visibility.frag";
  std::vector<float> expected;
  std::vector<bool> inside;
  while (static_cast<int>(request.in0.size()) < kProbePoints) {
    // A texel index from 4 outside the map to 4 beyond it, a place inside it away from its borders.
    auto coordinate = [&] {
      const float texel = std::floor(unit(rng) * (kProbeMapSize + 8)) - 4.0f;
      return (texel + kBorderMargin + (1.0f - 2.0f * kBorderMargin) * unit(rng)) / kProbeMapSize;
    };
    const glm::vec3 s(coordinate(), coordinate(), -0.1f + 1.2f * unit(rng));
    const bool in = s.x >= 0 && s.x <= 1 && s.y >= 0 && s.y <= 1 && s.z >= 0 && s.z <= 1;
    float reference = 1.0f;
    if (in) {
      const int ix = std::min(static_cast<int>(s.x * kProbeMapSize), kProbeMapSize - 1);
      const int iy = std::min(static_cast<int>(s.y * kProbeMapSize), kProbeMapSize - 1);
      const float stored = depths[static_cast<std::size_t>(iy * kProbeMapSize + ix)];
      if (s.z > stored - kDepthMargin && s.z < stored + kProbeBiasBand + kDepthMargin) continue;
      reference = s.z - kProbeBias > stored ? 0.0f : 1.0f;
    }
    request.in0.push_back(glm::vec4(2.0f * s - 1.0f, 1.0f));  // world = clip: x, y, z in [-1, 1]; n.l = 1
    request.in1.push_back({0, 0, 1, 0});
    expected.push_back(reference);
    inside.push_back(in);
  }
  const GlTexture map = make_probe_depth_texture(depths, kProbeMapSize);
  const GlSampler compare = make_compare_sampler();
  request.passes.push_back([&](GLuint program) {
    bind_probe_shadow_map(program, map, compare);
    set_uniform(program, "u_light_view_proj", glm::mat4(1.0f));
    set_uniform(program, "u_bias_constant", kProbeBias);
    set_uniform(program, "u_bias_slope", 0.0f);
    set_uniform(program, "u_texel_depth", 0.0f);
  });
  const std::vector<float> v = run_probe(ctx.hooks(), request).at(0);
  double wrong_inside = 0, wrong_outside = 0, n_inside = 0, n_outside = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const bool wrong = !(std::abs(v[i] - expected[i]) <= 1e-3f);
    (inside[i] ? wrong_inside : wrong_outside) += wrong;
    (inside[i] ? n_inside : n_outside) += 1;
  }
  const std::string why = "probe: 64x64 map of random depths, points inside and outside it; 0.2 % for rounding";
  result.metrics["probe"] = {{"map_size", kProbeMapSize}, {"points_inside", n_inside}, {"points_outside", n_outside},
                             {"wrong_inside", wrong_inside}, {"wrong_outside", wrong_outside}};
  result.criteria.push_back({"probe.lookup_mismatch", wrong_inside / std::max(n_inside, 1.0), Criterion::kAtMost,
                             kMaxProbeMismatch, why,
                             "each point must read the texel it falls in: x, y and z from [-1, 1] to [0, 1] (scale 0.5, "
                             "offset 0.5), the texel at floor(uv * size), compared with the biased depth."});
  result.criteria.push_back({"probe.outside_map_mismatch", wrong_outside / std::max(n_outside, 1.0), Criterion::kAtMost,
                             kMaxProbeMismatch, why,
                             "outside the light's map nothing was drawn, so nothing can hide the point: return 1 there."});
}

// Lab 0's GL exercise (gl_setup.h): the graded gl_shadow_target.cpp (the file on disk, a submission's, or
// the solution: the renderer's renderer/shadow_target.cpp) is built with its host and run in the sandbox.
constexpr const char* kGlExercise = SHADOWLAB_LAB_FOLDER "/gl_shadow_target.cpp";
constexpr const char* kGlSolution = "renderer/shadow_target.cpp";
// The lab folder's exercise host (labs/CMakeLists.txt): the folder's name.
const std::string kHost = std::string(SHADOWLAB_LAB_FOLDER).substr(std::string("labs/").size());
// A map size that is no power of two (a size written into the code is found out) in a window larger
// than the map (a viewport left at the window's size is found out).
constexpr TargetCall kCall{300, 1280, 720};
// State is exact: no texel, pixel, wrong parameter or error is allowed.
constexpr double kNoDifference = 0;
// A read of the probe may differ from a stored depth by one step of the coarsest depth format (16 bits).
constexpr double kReadTolerance = 1.0 / 65535.0;
// The fewest depth bits a depth format has (GL_DEPTH_COMPONENT16); a colour texture has 0.
constexpr int kMinDepthBits = 16;

std::string enum_name(int value) {
  static const std::map<int, std::string> names = {
      {GL_NONE, "GL_NONE"}, {GL_NEAREST, "GL_NEAREST"}, {GL_LINEAR, "GL_LINEAR"},
      {GL_NEAREST_MIPMAP_NEAREST, "GL_NEAREST_MIPMAP_NEAREST"}, {GL_LINEAR_MIPMAP_LINEAR, "GL_LINEAR_MIPMAP_LINEAR"},
      {GL_NEAREST_MIPMAP_LINEAR, "GL_NEAREST_MIPMAP_LINEAR"}, {GL_LINEAR_MIPMAP_NEAREST, "GL_LINEAR_MIPMAP_NEAREST"},
      {GL_REPEAT, "GL_REPEAT"}, {GL_MIRRORED_REPEAT, "GL_MIRRORED_REPEAT"}, {GL_CLAMP_TO_EDGE, "GL_CLAMP_TO_EDGE"},
      {GL_CLAMP_TO_BORDER, "GL_CLAMP_TO_BORDER"}, {GL_TEXTURE, "GL_TEXTURE"}, {GL_RENDERBUFFER, "GL_RENDERBUFFER"},
      {GL_FRAMEBUFFER_COMPLETE, "GL_FRAMEBUFFER_COMPLETE"},
      {GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"},
      {GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT, "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"},
      {GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER, "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER"},
      {GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER, "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER"},
      {GL_FRAMEBUFFER_UNSUPPORTED, "GL_FRAMEBUFFER_UNSUPPORTED"}, {GL_FRAMEBUFFER_UNDEFINED, "GL_FRAMEBUFFER_UNDEFINED"},
      {GL_COLOR_ATTACHMENT0, "GL_COLOR_ATTACHMENT0"}, {GL_BACK, "GL_BACK"}, {GL_FRONT, "GL_FRONT"},
      {GL_DEPTH_COMPONENT, "GL_DEPTH_COMPONENT"}, {GL_DEPTH_COMPONENT16, "GL_DEPTH_COMPONENT16"},
      {GL_DEPTH_COMPONENT24, "GL_DEPTH_COMPONENT24"}, {GL_DEPTH_COMPONENT32, "GL_DEPTH_COMPONENT32"},
      {GL_DEPTH_COMPONENT32F, "GL_DEPTH_COMPONENT32F"}, {GL_RGBA8, "GL_RGBA8"}, {GL_RGBA, "GL_RGBA"},
      {GL_RGBA32F, "GL_RGBA32F"}, {GL_R32F, "GL_R32F"}, {GL_RG32F, "GL_RG32F"},
      {GL_INVALID_ENUM, "GL_INVALID_ENUM"}, {GL_INVALID_VALUE, "GL_INVALID_VALUE"},
      {GL_INVALID_OPERATION, "GL_INVALID_OPERATION"}, {GL_INVALID_FRAMEBUFFER_OPERATION, "GL_INVALID_FRAMEBUFFER_OPERATION"},
      {GL_OUT_OF_MEMORY, "GL_OUT_OF_MEMORY"}};
  const auto found = names.find(value);
  if (found != names.end()) return found->second;
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(value));
  return hex;
}

nlohmann::json state_json(const TargetState& s) {
  return {{"gl_error_after_create", enum_name(s.gl_error_after_create)}, {"is_framebuffer", s.is_framebuffer != 0},
          {"is_texture", s.is_texture != 0}, {"size", s.size}, {"status", enum_name(s.status)},
          {"depth_attachment_type", enum_name(s.depth_attachment_type)},
          {"depth_attachment_is_the_texture", s.depth_attachment_name == s.texture && s.texture != 0},
          {"colour_attachment_type", enum_name(s.colour_attachment_type)}, {"draw_buffer", enum_name(s.draw_buffer)},
          {"read_buffer", enum_name(s.read_buffer)}, {"internal_format", enum_name(s.internal_format)},
          {"width", s.width}, {"height", s.height}, {"depth_bits", s.depth_bits},
          {"min_filter", enum_name(s.min_filter)}, {"mag_filter", enum_name(s.mag_filter)},
          {"wrap_s", enum_name(s.wrap_s)}, {"wrap_t", enum_name(s.wrap_t)},
          {"border", {s.border[0], s.border[1], s.border[2], s.border[3]}},
          {"gl_error_after_begin", enum_name(s.gl_error_after_begin)},
          {"pass_binds_the_target", s.pass_framebuffer == s.framebuffer && s.framebuffer != 0},
          {"viewport", {s.viewport[0], s.viewport[1], s.viewport[2], s.viewport[3]}},
          {"depth_min", s.depth_min}, {"depth_max", s.depth_max},
          {"probe_reads", {s.probe_reads[0], s.probe_reads[1], s.probe_reads[2], s.probe_reads[3], s.probe_reads[4]}}};
}

std::string completeness_advice(const TargetState& s) {
  if (!s.is_framebuffer)
    return "target.framebuffer is no framebuffer: make one with glGenFramebuffers and bind it (glBindFramebuffer) "
           "before attaching to it.";
  switch (s.status) {
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "the framebuffer has no image: attach the depth texture with glFramebufferTexture2D(GL_FRAMEBUFFER, "
             "GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture, 0).";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "the attached texture cannot be a depth attachment: give it a depth format (glTexImage2D with "
             "GL_DEPTH_COMPONENT24 and GL_DEPTH_COMPONENT), and attach it to GL_DEPTH_ATTACHMENT.";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
      return "the framebuffer draws to or reads from a colour attachment it does not have: glDrawBuffer(GL_NONE) "
             "and glReadBuffer(GL_NONE) with it bound.";
    default:
      return "glCheckFramebufferStatus says " + enum_name(s.status) + ": attach a depth texture and nothing else.";
  }
}

bool clamps(int wrap, float border) { return wrap == GL_CLAMP_TO_EDGE || (wrap == GL_CLAMP_TO_BORDER && border >= 1.0f); }

void add_criteria(const TargetState& s, CheckResult& result) {
  auto& c = result.criteria;
  const std::string read = "read back after create_shadow_target(300) with glGet* (an OpenGL state, not a tolerance)";
  c.push_back({"gl_setup.framebuffer_complete", s.status == GL_FRAMEBUFFER_COMPLETE ? 1.0 : 0.0, Criterion::kAtLeast, 1.0,
               "glCheckFramebufferStatus with target.framebuffer bound: GL_FRAMEBUFFER_COMPLETE", completeness_advice(s)});
  const bool attached = s.depth_attachment_type == GL_TEXTURE && s.depth_attachment_name == s.texture && s.texture != 0;
  c.push_back({"gl_setup.depth_attachment_is_the_map", attached ? 1.0 : 0.0, Criterion::kAtLeast, 1.0,
               "GL_DEPTH_ATTACHMENT's object is target.depth_texture (glGetFramebufferAttachmentParameteriv)",
               "attach target.depth_texture (not a renderbuffer, not another texture) to GL_DEPTH_ATTACHMENT: the lit "
               "pass reads the map through target.depth_texture."});
  c.push_back({"gl_setup.depth_bits", static_cast<double>(s.depth_bits), Criterion::kAtLeast, kMinDepthBits,
               "GL_TEXTURE_DEPTH_SIZE of the map's level 0; 16 bits is the smallest depth format",
               "the map must be a depth texture: internal format GL_DEPTH_COMPONENT24 (or 16, 32F) with format "
               "GL_DEPTH_COMPONENT; a colour texture (GL_RGBA8) stores no depth and cannot be the depth attachment."});
  const double size_error = std::abs(s.width - kCall.size) + std::abs(s.height - kCall.size) + std::abs(s.size - kCall.size);
  c.push_back({"gl_setup.map_size_error", size_error,
               Criterion::kAtMost, kNoDifference, "texels between the map's width, height, target.size and the size asked for (300)",
               "make the texture size x size, with the size the function is given, and return it in target.size."});
  const double filters = (s.min_filter != GL_NEAREST) + (s.mag_filter != GL_NEAREST);
  c.push_back({"gl_setup.filters_not_nearest", filters, Criterion::kAtMost, kNoDifference, read,
               "GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER must both be GL_NEAREST: one comparison reads one "
               "texel; a linear filter blends the depths of two surfaces into a depth no surface has (and the default "
               "minification filter uses mipmaps the map does not have)."});
  const double wraps = !clamps(s.wrap_s, s.border[0]) + !clamps(s.wrap_t, s.border[0]);
  c.push_back({"gl_setup.wraps_not_clamped", wraps, Criterion::kAtMost, kNoDifference, read,
               "GL_TEXTURE_WRAP_S and _T must be GL_CLAMP_TO_EDGE, or GL_CLAMP_TO_BORDER with a border depth of 1: "
               "with GL_REPEAT (the default) a point beyond the map's edge reads the other side of the map, and a "
               "shadow from there appears where nothing casts one."});
  const double colour = (s.draw_buffer != GL_NONE) + (s.read_buffer != GL_NONE);
  c.push_back({"gl_setup.colour_buffers_named", colour, Criterion::kAtMost, kNoDifference,
               "GL_DRAW_BUFFER and GL_READ_BUFFER with target.framebuffer bound; OpenGL 3.3 (section 4.4.4) makes a "
               "framebuffer that draws to an attachment it lacks incomplete",
               "call glDrawBuffer(GL_NONE) and glReadBuffer(GL_NONE) with the framebuffer bound: it has no colour "
               "buffer. Mesa reports it complete without them (it implements the rule of OpenGL 4.1, which dropped "
               "the check), an OpenGL 3.3 driver may not."});
  const double bound = s.pass_framebuffer == s.framebuffer && s.framebuffer != 0 ? 0.0 : 1.0;
  c.push_back({"gl_setup.pass_not_into_the_map", bound, Criterion::kAtMost, kNoDifference,
               "GL_DRAW_FRAMEBUFFER_BINDING after begin_shadow_pass is target.framebuffer",
               "begin_shadow_pass must bind target.framebuffer (glBindFramebuffer(GL_FRAMEBUFFER, ...)): otherwise the "
               "depth pass draws into the window."});
  const double viewport = std::abs(s.viewport[0]) + std::abs(s.viewport[1]) + std::abs(s.viewport[2] - kCall.size) +
                          std::abs(s.viewport[3] - kCall.size);
  c.push_back({"gl_setup.viewport_error", viewport, Criterion::kAtMost, kNoDifference,
               "pixels between GL_VIEWPORT after begin_shadow_pass and (0, 0, 300, 300); it was the window's 1280 x 720",
               "glViewport(0, 0, target.size, target.size) in begin_shadow_pass: the viewport is not part of the "
               "framebuffer, and the window's leaves most of the scene outside the map (or the map's corner only)."});
  const double uncleared = s.depth_min < 0.0f ? 1.0 : 1.0 - s.depth_min;
  c.push_back({"gl_setup.depth_below_far_after_clear", uncleared, Criterion::kAtMost, kNoDifference,
               "1 - the smallest depth in the map after begin_shadow_pass; the map held 0.25 before it (a last frame's)",
               "clear the map's depth in begin_shadow_pass (glClear(GL_DEPTH_BUFFER_BIT) with the clear depth 1, the "
               "default): otherwise last frame's depths stay, and surfaces that moved away still cast shadows."});
  // What a lit pass reads (gl_setup.h, kProbeUv): under the occluder its depth; in the open and beyond the
  // map's edges beside the open quarters the far plane; on the occluder's edge either.
  const float under = kOccluderDepth, open = 1.0f;
  const std::vector<std::vector<float>> right_reads = {{under}, {open}, {open}, {open}, {under, open}};
  double wrong_reads = 0;
  for (std::size_t i = 0; i < right_reads.size(); ++i)
    wrong_reads += std::none_of(right_reads[i].begin(), right_reads[i].end(),
                                [&](float r) { return std::abs(s.probe_reads[i] - r) <= kReadTolerance; });
  c.push_back({"gl_setup.probe_reads_wrong", wrong_reads, Criterion::kAtMost, kNoDifference,
               "an occluder at depth 0.3 drawn over the map's lower left quarter through begin_shadow_pass's state, "
               "then the map read with texture() at 5 points, as a lit pass reads it (probe_reads in the metrics)",
               "what the lit pass would read is wrong at some of the 5 points (under the occluder 0.3; in the open, "
               "and just beyond the right and top edges beside the open quarters, 1; on the occluder's edge 0.3 or 1): "
               "the state criteria above say which setting shows (a repeating map reads the occluder beyond the edge, "
               "a linear filter a blend on its edge, an uncleared map or a window-sized viewport 0.25 or 0.3 in the open)."});
  const double errors = (s.gl_error_after_create != GL_NO_ERROR) + (s.gl_error_after_begin != GL_NO_ERROR);
  c.push_back({"gl_setup.gl_errors", errors, Criterion::kAtMost, kNoDifference,
               "glGetError after create_shadow_target and after begin_shadow_pass",
               "a call failed (see gl_error_after_create and _begin in the metrics): check each call's arguments "
               "against the OpenGL 3.3 reference."});
}

// The GL exercise graded: the file built and run in the sandbox with its own headless OpenGL context, the
// state it left turned into the gl_setup.* criteria.
void check_gl_setup(CheckContext& ctx, CheckResult& result) {
  std::optional<CppExerciseSpec> spec =
      gl_exercise_spec(ctx, result, kGlExercise, kGlSolution, kHost, "gl_setup", "lab 0's OpenGL part");
  if (!spec) return;
  spec->headers = {SHADOWLAB_LAB_FOLDER "/gl_setup.h", "renderer/shadow_target.h", "renderer/gl.h"};
  CppExercise program(*spec);
  const TargetState state = program.call<TargetState>(kCall);
  result.metrics["gl_setup"] = state_json(state);
  add_criteria(state, result);
}

void check_basic(CheckContext& ctx, CheckResult& result) {
  check_gl_setup(ctx, result);
  probe_shadow_test(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  // The lab's own scene and light, then held-out lights, map sizes and scenes: the bias matrix is the
  // same for every one.
  ParamSet sloped = params;
  sloped.set("shadow.slope_bias", kHeldOutSlopeBias);
  grade_lab_and_held_out_lights(ctx, result, "lab00", "lab_light", params, sloped, kHeldOut, kLimits);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Basic shadow map";
  lab.summary = "Two passes: depth from the light, then one depth comparison per pixel.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.gl_exercise_files = {SHADOWLAB_LAB_FOLDER "/gl_shadow_target.cpp"};
  lab.gl_solution_files = {"renderer/shadow_target.cpp"};
  lab.presets = {
      {"acne", "No bias: surfaces shadow themselves in stripes.", {{"shadow.bias", "0"}},
       {.provokes = "acne", .fixed_by = "tutorial"}},
      {"peter-panning", "A huge bias under a low light, seen from the thin plate's foot: its shadow detaches from it.",
       {{"shadow.bias", "0.05"}, {"light.elevation", "20"}},
       {.provokes = "peter-panning", .fixed_by = "tutorial"}, {.camera = "eye=-1.6,0.7,2.6 target=0.1,0.1,0.4 fov=40"}},
      {"tutorial", "The tutorial's constant bias of 0.005.", {{"shadow.bias", "0.005"}}},
  };
  lab.offered_includes = {"lab/bias.glsl"};
  // The bias matrix is the lesson: the exercise's programs hold nothing that maps into the shadow map
  // for it (Features::own_shadow_coords; the audit in INSTRUCTOR.md).
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks = visibility_lab_hooks()(files);
    hooks.own_shadow_coords = true;
    return hooks;
  };
  lab.check = check_basic;
  return lab;
}

}  // namespace shadowlab
