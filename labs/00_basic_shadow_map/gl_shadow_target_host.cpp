// main() of lab 0's GL exercise when grading builds it (grading/cpp_exercise.h, `renders`): a headless
// OpenGL context first, then each TargetCall is answered with what create_shadow_target and
// begin_shadow_pass left (labs/00_basic_shadow_map/gl_setup.h). Not part of the shadowlab binary.
#include <algorithm>
#include <iterator>
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

// The depth pass and a lit pass through the student's state: an occluder drawn at kOccluderDepth over
// the lower left quarter of NDC with the binding and viewport begin_shadow_pass left, then the map read
// with texture() at kProbeUv, one pixel each.
void probe(GLuint depth_texture, TargetState& s) {
  GLuint vao = 0, colour = 0, framebuffer = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  const GLuint occluder = compile_exercise_program(
      "#version 330 core\nuniform float u_z;\n"
      "void main() { gl_Position = vec4(vec2(gl_VertexID & 1, gl_VertexID >> 1) - 1.0, u_z, 1.0); }\n",
      "#version 330 core\nvoid main() {}\n");
  glUseProgram(occluder);
  glUniform1f(glGetUniformLocation(occluder, "u_z"), 2.0f * kOccluderDepth - 1.0f);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  constexpr int kPoints = static_cast<int>(std::size(kProbeUv));
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, kPoints, 1, 0, GL_RED, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  glViewport(0, 0, kPoints, 1);
  glDisable(GL_DEPTH_TEST);
  const GLuint reader = compile_exercise_program(
      "#version 330 core\nvoid main() { gl_Position = vec4(vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0, 0.0, 1.0); }\n",
      "#version 330 core\nuniform sampler2D u_map;\nuniform vec2 u_uv[5];\nout vec4 read;\n"
      "void main() { read = vec4(texture(u_map, u_uv[int(gl_FragCoord.x)]).r); }\n");
  glUseProgram(reader);
  glUniform2fv(glGetUniformLocation(reader, "u_uv"), kPoints, &kProbeUv[0][0]);
  glUniform1i(glGetUniformLocation(reader, "u_map"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, depth_texture);
  glBindSampler(0, 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glReadPixels(0, 0, kPoints, 1, GL_RED, GL_FLOAT, s.probe_reads);
  glUseProgram(0);
  glDeleteProgram(occluder);
  glDeleteProgram(reader);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &colour);
  glDeleteVertexArrays(1, &vao);
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
    probe(target.depth_texture, s);  // the draw binding and the viewport are still the pass's
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &target.framebuffer);
  glDeleteTextures(1, &target.depth_texture);
  return s;
}

}  // namespace

int main() { return serve_exercise<TargetCall, TargetState>(answer, make_exercise_gl_context); }
