// The solution of lab 5's GL exercise, and the renderer's own code path (renderer/blur_passes.h).
#include "renderer/blur_passes.h"

namespace shadowlab {

BlurTarget create_blur_target(int size, GLenum internal_format) {
  BlurTarget target;
  target.size = size;
  // 1. The texture: the moments' format (32-bit floats: 8-bit channels would quantise E[z^2]) and size.
  const bool four = internal_format == GL_RGBA32F || internal_format == GL_RGBA16F;
  glGenTextures(1, &target.texture);
  glBindTexture(GL_TEXTURE_2D, target.texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), size, size, 0, four ? GL_RGBA : GL_RG, GL_FLOAT,
               nullptr);
  // 2. No mipmaps: a minification filter that needs them would leave the texture incomplete (reads 0).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // 3. A tap beyond the edge reads the edge texel, never the other side of the map.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  // 4. The framebuffer: the texture as its only colour buffer; no depth buffer (the passes test no depth).
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

namespace {

// One pass: draws into `framebuffer` over the whole map, reading `source` on unit 0 along `direction`.
void blur_pass(const BlurJob& job, int pass, GLuint framebuffer, GLuint source, GLuint program, float dx, float dy) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  const GLenum colour = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &colour);
  glViewport(0, 0, job.size, job.size);  // the map's texels, not the window's pixels
  glUseProgram(program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source);  // never the texture `framebuffer` writes: a feedback loop
  glUniform1i(glGetUniformLocation(program, "u_moments"), 0);
  glUniform2f(glGetUniformLocation(program, "u_direction"), dx, dy);
  const float texel = 1.0f / static_cast<float>(job.size);
  glUniform2f(glGetUniformLocation(program, "u_texel_size"), texel, texel);
  job.draw(pass);
}

}  // namespace

void run_blur_passes(const BlurJob& job) {
  // The moments framebuffer keeps the moments pass's depth buffer: a depth test would discard the blur
  // wherever a caster is nearer than the full-screen triangle.
  glDisable(GL_DEPTH_TEST);
  blur_pass(job, 0, job.target.framebuffer, job.moments_texture, job.program_x, 1.0f, 0.0f);  // X: A -> B
  blur_pass(job, 1, job.moments_framebuffer, job.target.texture, job.program_y, 0.0f, 1.0f);  // Y: B -> A
}

}  // namespace shadowlab
