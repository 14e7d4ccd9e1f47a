// Lab 5's GL exercise: the ping-pong target of the moments' blur and its two passes, in OpenGL (the
// course's separable blur: two passes, two shaders). Edit both functions, then: shadowlab check --lab 5
// What each call does and why: this lab's text (README.md, "The two passes in OpenGL").
#include "labs/05_moment_blur/gl_setup.h"

namespace shadowlab {

BlurTarget create_blur_target(int size, GLenum internal_format) {
  BlurTarget target;
  target.size = size;
  // TODO: the intermediate texture and the framebuffer that draws into it.
  //   1. A texture (glGenTextures, glBindTexture(GL_TEXTURE_2D, ...)) with storage for size x size
  //      moments in internal_format (the moments' own: GL_RG32F, or GL_RGBA32F for four moments) with
  //      glTexImage2D (format GL_RG or GL_RGBA, type GL_FLOAT).
  //   2. Its filtering (GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER): the default minification filter
  //      reads mipmaps, which this texture does not have.
  //   3. Its wrap (GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T): a tap beyond the edge reads the edge texel.
  //   4. A framebuffer (glGenFramebuffers, glBindFramebuffer) with the texture as GL_COLOR_ATTACHMENT0
  //      (glFramebufferTexture2D).
  //   5. Bind framebuffer 0 again before returning.
  (void)internal_format;
  glGenTextures(1, &target.texture);
  return target;
}

void run_blur_passes(const BlurJob& job) {
  // TODO: the two passes, each: bind the framebuffer it draws into, set the viewport to the whole map,
  // use its program, bind the texture it reads on a texture unit and name that unit in the sampler
  // uniform "u_moments", set "u_direction" ((1, 0) for X, (0, 1) for Y) and "u_texel_size" (1 / size),
  // then job.draw(pass). X reads job.moments_texture into job.target; Y reads job.target.texture back into
  // job.moments_framebuffer, where the lit pass reads the result. The depth test must be off: the moments
  // framebuffer keeps the moments pass's depth buffer.
  glUseProgram(job.program_x);
  job.draw(0);
}

}  // namespace shadowlab
