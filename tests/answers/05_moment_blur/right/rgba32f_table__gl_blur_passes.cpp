// right: an RGBA32F target attached with glFramebufferTexture, the passes from a table, the texel
// size computed in double
// expect: variant
#include "labs/05_moment_blur/gl_setup.h"

namespace shadowlab {

BlurTarget create_blur_target(int size, GLenum internal_format) {
  BlurTarget target;
  target.size = size;
  glGenTextures(1, &target.texture);
  glBindTexture(GL_TEXTURE_2D, target.texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size, size, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target.texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}


void run_blur_passes(const BlurJob& job) {
  struct Pass {
    GLuint framebuffer, source, program;
    float direction[2];
  };
  const Pass passes[2] = {{job.target.framebuffer, job.moments_texture, job.program_x, {1, 0}},
                          {job.moments_framebuffer, job.target.texture, job.program_y, {0, 1}}};
  const double texel = 1.0 / job.size;
  glDisable(GL_DEPTH_TEST);
  glViewport(0, 0, job.size, job.size);
  for (int i = 0; i < 2; ++i) {
    glBindFramebuffer(GL_FRAMEBUFFER, passes[i].framebuffer);
    glUseProgram(passes[i].program);
    glBindTexture(GL_TEXTURE_2D, passes[i].source);
    glUniform2f(glGetUniformLocation(passes[i].program, "u_direction"), passes[i].direction[0], passes[i].direction[1]);
    glUniform2f(glGetUniformLocation(passes[i].program, "u_texel_size"), static_cast<float>(texel), static_cast<float>(texel));
    job.draw(i);
  }
}

}  // namespace shadowlab
