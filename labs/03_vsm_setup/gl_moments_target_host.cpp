// main() of lab 3's GL exercise when grading builds it (grading/cpp_exercise.h, `renders`): a headless
// OpenGL context first, then each MomentsCall is answered with what create_moments_target and
// begin_moments_pass left (labs/03_vsm_setup/gl_setup.h). Not part of the shadowlab binary.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "labs/03_vsm_setup/gl_setup.h"
#include "grading/cpp_exercise_host.h"
#include "grading/gl_exercise_host.h"

namespace {

using namespace shadowlab;
using namespace shadowlab::moments_probe;

void read_texture(GLuint texture, MomentsState& s) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &s.internal_format);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &s.width);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &s.height);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &s.red_bits);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &s.green_bits);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE, &s.red_type);
  read_texture_sampling(s.min_filter, s.mag_filter, s.wrap_s, s.wrap_t, s.border);
  glBindTexture(GL_TEXTURE_2D, 0);
}

void read_framebuffer(GLuint framebuffer, MomentsState& s) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  s.status = static_cast<int>(glCheckFramebufferStatus(GL_FRAMEBUFFER));
  const auto attachment = [](GLenum which, int& type, int& name) {
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, which, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_NONE) glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, which, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
  };
  attachment(GL_COLOR_ATTACHMENT0, s.colour_attachment_type, s.colour_attachment_name);
  attachment(GL_DEPTH_ATTACHMENT, s.depth_attachment_type, s.depth_attachment_name);
  if (s.depth_attachment_type != GL_NONE)
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                          &s.depth_bits);
  if (s.status == GL_FRAMEBUFFER_COMPLETE) {  // last frame's moments and depths, which the pass must clear
    glViewport(0, 0, s.size, s.size);
    glDepthMask(GL_TRUE);
    glClearBufferfv(GL_COLOR, 0, kStainMoments);  // leaves the clear colour as it was
    glClearBufferfv(GL_DEPTH, 0, &kStainDepth);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// The moments pass and a lit pass through the student's state: the moments (z, z^2) of an occluder at
// kNearDepth over the lower left quarter of NDC, then of one at kFarDepth over the left half, with the
// binding and viewport begin_moments_pass left and the depth test on; then the map read with texture()
// at kProbeUv and Chebyshev's bound for a receiver at kReceiverDepth, one pixel each.
void probe(GLuint moments_texture, MomentsState& s) {
  GLuint vao = 0, colour = 0, framebuffer = 0;
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  const GLuint occluder = compile_exercise_program(
      "#version 330 core\nuniform float u_z;\nuniform float u_height;\n"
      "void main() { gl_Position = vec4(float(gl_VertexID & 1) - 1.0, float(gl_VertexID >> 1) * u_height - 1.0, u_z, 1.0); }\n",
      "#version 330 core\nout vec4 moments;\n"
      "void main() { float z = gl_FragCoord.z; moments = vec4(z, z * z, 0.0, 0.0); }\n");
  glUseProgram(occluder);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  for (const auto& [depth, height] : {std::pair{kNearDepth, 1.0f}, std::pair{kFarDepth, 2.0f}}) {
    glUniform1f(glGetUniformLocation(occluder, "u_z"), 2.0f * depth - 1.0f);
    glUniform1f(glGetUniformLocation(occluder, "u_height"), height);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  glGenTextures(1, &colour);
  glBindTexture(GL_TEXTURE_2D, colour);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kGlProbePoints, 1, 0, GL_RGBA, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  glViewport(0, 0, kGlProbePoints, 1);
  glDisable(GL_DEPTH_TEST);
  const GLuint reader = compile_exercise_program(
      "#version 330 core\nvoid main() { gl_Position = vec4(vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0, 0.0, 1.0); }\n",
      "#version 330 core\nuniform sampler2D u_map;\nuniform vec2 u_uv[5];\nuniform float u_z[5];\n"
      "uniform float u_min_variance;\nout vec4 read;\n"
      "void main() {\n  int i = int(gl_FragCoord.x);\n  vec2 m = texture(u_map, u_uv[i]).rg;\n"
      "  float variance = max(m.y - m.x * m.x, u_min_variance), d = u_z[i] - m.x;\n"
      "  read = vec4(m, u_z[i] <= m.x ? 1.0 : variance / (variance + d * d), 0.0);\n}\n");
  glUseProgram(reader);
  glUniform2fv(glGetUniformLocation(reader, "u_uv"), kGlProbePoints, &kProbeUv[0][0]);
  glUniform1fv(glGetUniformLocation(reader, "u_z"), kGlProbePoints, kReceiverDepth);
  glUniform1f(glGetUniformLocation(reader, "u_min_variance"), kProbeMinVariance);
  glUniform1i(glGetUniformLocation(reader, "u_map"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, moments_texture);
  glBindSampler(0, 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  float reads[kGlProbePoints][4];
  glReadPixels(0, 0, kGlProbePoints, 1, GL_RGBA, GL_FLOAT, reads);
  for (int i = 0; i < kGlProbePoints; ++i) {
    s.probe_moments[i][0] = reads[i][0];
    s.probe_moments[i][1] = reads[i][1];
    s.probe_bounds[i] = reads[i][2];
  }
  glUseProgram(0);
  glDeleteProgram(occluder);
  glDeleteProgram(reader);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &colour);
  glDeleteVertexArrays(1, &vao);
}

// The moments and depths the pass left before anything is drawn: each should be the clear value.
void read_cleared(const MomentsTarget& target, MomentsState& s) {
  const std::size_t texels = static_cast<std::size_t>(target.size) * static_cast<std::size_t>(target.size);
  std::vector<float> moments(2 * texels), depth(texels);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, target.size, target.size, GL_RG, GL_FLOAT, moments.data());
  if (glGetError() == GL_NO_ERROR) {
    s.moments_off_clear = 0;
    for (float m : moments) s.moments_off_clear = std::max(s.moments_off_clear, std::abs(m - 1.0f));
  }
  glReadPixels(0, 0, target.size, target.size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  if (glGetError() == GL_NO_ERROR) s.depth_min = *std::min_element(depth.begin(), depth.end());
}

MomentsState answer(const MomentsCall& call) {
  MomentsState s;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, call.window_width, call.window_height);
  while (glGetError() != GL_NO_ERROR) {
  }
  const MomentsTarget target = create_moments_target(call.size);
  s.gl_error_after_create = static_cast<int>(glGetError());
  s.size = target.size;
  s.framebuffer = static_cast<int>(target.framebuffer);
  s.texture = static_cast<int>(target.moments_texture);
  s.renderbuffer = static_cast<int>(target.depth_renderbuffer);
  s.is_framebuffer = glIsFramebuffer(target.framebuffer);
  s.is_texture = glIsTexture(target.moments_texture);
  s.is_renderbuffer = glIsRenderbuffer(target.depth_renderbuffer);
  if (s.is_texture) read_texture(target.moments_texture, s);
  if (s.is_renderbuffer) {
    glBindRenderbuffer(GL_RENDERBUFFER, target.depth_renderbuffer);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &s.renderbuffer_format);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
  }
  if (s.is_framebuffer) read_framebuffer(target.framebuffer, s);
  while (glGetError() != GL_NO_ERROR) {
  }
  // The pass begins as the renderer's frame would: the window's framebuffer and viewport current.
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, call.window_width, call.window_height);
  begin_moments_pass(target);
  s.gl_error_after_begin = static_cast<int>(glGetError());
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.pass_framebuffer);
  glGetIntegerv(GL_VIEWPORT, s.viewport);
  if (s.status == GL_FRAMEBUFFER_COMPLETE && s.width == call.size && s.height == call.size) {
    read_cleared(target, s);
    probe(target.moments_texture, s);  // the draw binding and the viewport are still the pass's
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &target.framebuffer);
  glDeleteTextures(1, &target.moments_texture);
  glDeleteRenderbuffers(1, &target.depth_renderbuffer);
  return s;
}

}  // namespace

int main() { return serve_exercise<MomentsCall, MomentsState>(answer, make_exercise_gl_context); }
