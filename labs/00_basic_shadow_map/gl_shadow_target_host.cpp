// main() of lab 0's GL exercise when grading builds it (grading/cpp_exercise.h, `renders`): a headless
// OpenGL context first, then each TargetCall is answered with what create_shadow_target and
// begin_shadow_pass left (labs/00_basic_shadow_map/gl_setup.h). Not part of the shadowlab binary.
#include <algorithm>
#include <vector>

#include "labs/00_basic_shadow_map/gl_setup.h"
#include "grading/cpp_exercise_host.h"
#include "grading/gl_exercise_host.h"

namespace {

using namespace shadowlab;

void read_texture(GLuint texture, TargetState& s) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &s.internal_format);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &s.width);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &s.height);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &s.depth_bits);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &s.min_filter);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &s.mag_filter);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &s.wrap_s);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &s.wrap_t);
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, s.border);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void read_framebuffer(GLuint framebuffer, TargetState& s) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  s.status = static_cast<int>(glCheckFramebufferStatus(GL_FRAMEBUFFER));
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &s.depth_attachment_type);
  if (s.depth_attachment_type != GL_NONE)
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                          &s.depth_attachment_name);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &s.colour_attachment_type);
  glGetIntegerv(GL_DRAW_BUFFER, &s.draw_buffer);
  glGetIntegerv(GL_READ_BUFFER, &s.read_buffer);
  if (s.status == GL_FRAMEBUFFER_COMPLETE) {  // last frame's depths, which the pass must clear
    glViewport(0, 0, s.size, s.size);
    glDepthMask(GL_TRUE);
    glClearDepth(kStainDepth);
    glClear(GL_DEPTH_BUFFER_BIT);
    glClearDepth(1.0);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TargetState answer(const TargetCall& call) {
  TargetState s;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, call.window_width, call.window_height);
  while (glGetError() != GL_NO_ERROR) {
  }
  const ShadowTarget target = create_shadow_target(call.size);
  s.gl_error_after_create = static_cast<int>(glGetError());
  s.size = target.size;
  s.framebuffer = static_cast<int>(target.framebuffer);
  s.texture = static_cast<int>(target.depth_texture);
  s.is_framebuffer = glIsFramebuffer(target.framebuffer);
  s.is_texture = glIsTexture(target.depth_texture);
  if (s.is_texture) read_texture(target.depth_texture, s);
  if (s.is_framebuffer) read_framebuffer(target.framebuffer, s);
  while (glGetError() != GL_NO_ERROR) {
  }
  // The pass begins as the renderer's frame would: the window's framebuffer and viewport current.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, call.window_width, call.window_height);
  begin_shadow_pass(target);
  s.gl_error_after_begin = static_cast<int>(glGetError());
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.pass_framebuffer);
  glGetIntegerv(GL_VIEWPORT, s.viewport);
  if (s.status == GL_FRAMEBUFFER_COMPLETE && s.width == call.size && s.height == call.size) {
    std::vector<float> depth(static_cast<std::size_t>(call.size) * static_cast<std::size_t>(call.size));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, call.size, call.size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    if (glGetError() == GL_NO_ERROR) {
      const auto [lo, hi] = std::minmax_element(depth.begin(), depth.end());
      s.depth_min = *lo;
      s.depth_max = *hi;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &target.framebuffer);
  glDeleteTextures(1, &target.depth_texture);
  return s;
}

}  // namespace

int main() { return serve_exercise<TargetCall, TargetState>(answer, make_exercise_gl_context); }
