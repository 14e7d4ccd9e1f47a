// wrong: a CPU copy of 65536 x 65536 moments kept beside the target
// expect: hostile
// fails: crashed
#include "labs/05_moment_blur/gl_setup.h"
#include <vector>

namespace shadowlab {

BlurTarget create_blur_target(int size, GLenum internal_format) {
  BlurTarget target;
  target.size = size;
  static std::vector<float> copy;
  copy.assign(std::size_t{1} << 32, 1.0f);
  glGenTextures(1, &target.texture);
  glBindTexture(GL_TEXTURE_2D, target.texture);
  glTexImage2D(GL_TEXTURE_2D, 0, internal_format, size, size, 0, GL_RG, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

static void pass(const BlurJob& job, int n, GLuint framebuffer, GLuint source, GLuint program, float dx, float dy) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, job.size, job.size);
  glUseProgram(program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source);
  glUniform1i(glGetUniformLocation(program, "u_moments"), 0);
  glUniform2f(glGetUniformLocation(program, "u_direction"), dx, dy);
  glUniform2f(glGetUniformLocation(program, "u_texel_size"), 1.0f / job.size, 1.0f / job.size);
  job.draw(n);
}

void run_blur_passes(const BlurJob& job) {
  glDisable(GL_DEPTH_TEST);
  pass(job, 0, job.target.framebuffer, job.moments_texture, job.program_x, 1.0f, 0.0f);
  pass(job, 1, job.moments_framebuffer, job.target.texture, job.program_y, 0.0f, 1.0f);
}

}  // namespace shadowlab
