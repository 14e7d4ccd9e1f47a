// Lab 0's GL exercise graded (labs/00_basic_shadow_map/gl_setup.h): the graded gl_shadow_target.cpp (the
// file on disk, a submission's, or the solution: the renderer's renderer/shadow_target.cpp) is built with
// its host and run in the sandbox with a headless OpenGL context; the state it left becomes criteria.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "labs/00_basic_shadow_map/gl_setup.h"
#include "renderer/shader.h"  // data_dir
#include "grading/check.h"
#include "grading/cpp_exercise.h"

namespace shadowlab {

namespace {

namespace fs = std::filesystem;

constexpr const char* kGlExercise = SHADOWLAB_LAB_FOLDER "/gl_shadow_target.cpp";
constexpr const char* kGlSolution = "renderer/shadow_target.cpp";
constexpr const char* kHost = "00_basic_shadow_map";
// A map size that is no power of two (a size written into the code is found out) in a window larger
// than the map (a viewport left at the window's size is found out).
constexpr TargetCall kCall{300, 1280, 720};
// State is exact: no texel, pixel, wrong parameter or error is allowed.
constexpr double kNoDifference = 0;
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
          {"depth_min", s.depth_min}, {"depth_max", s.depth_max}};
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
  const double errors = (s.gl_error_after_create != GL_NO_ERROR) + (s.gl_error_after_begin != GL_NO_ERROR);
  c.push_back({"gl_setup.gl_errors", errors, Criterion::kAtMost, kNoDifference,
               "glGetError after create_shadow_target and after begin_shadow_pass",
               "a call failed (see gl_error_after_create and _begin in the metrics): check each call's arguments "
               "against the OpenGL 3.3 reference."});
}

fs::path graded_file(const CheckContext& ctx) {
  if (!ctx.submission.empty()) return fs::absolute(ctx.submission / kGlExercise);
  return data_dir() / (ctx.impl == Impl::Solution ? kGlSolution : kGlExercise);
}

}  // namespace

void check_gl_setup(CheckContext& ctx, CheckResult& result) {
  const fs::path file = graded_file(ctx);
  if (!ctx.submission.empty() && !fs::is_regular_file(file)) {
    result.criteria.push_back({"gl_setup.file_submitted", 0.0, Criterion::kAtLeast, 1.0,
                               std::string(kGlExercise) + " in the submission",
                               std::string("hand in ") + kGlExercise + " too: lab 0's OpenGL part."});
    return;
  }
  if (const std::string why = cpp_exercise_unavailable(kHost); !why.empty()) {
    result.notes.push_back(std::string(kGlExercise) + " is not graded here: " + why);
    return;
  }
  CppExerciseSpec spec;
  spec.source = file;
  spec.display_name = ctx.impl == Impl::Solution && ctx.submission.empty() ? kGlSolution : kGlExercise;
  spec.host = kHost;
  spec.headers = {"labs/00_basic_shadow_map/gl_setup.h", "renderer/shadow_target.h", "renderer/gl.h"};
  spec.renders = true;
  CppExercise program(spec);
  const TargetState state = program.call<TargetState>(kCall);
  result.metrics["gl_setup"] = state_json(state);
  add_criteria(state, result);
}

}  // namespace shadowlab
