// Lab 3's GL exercise: the variance shadow map's render target and the start of its pass, in OpenGL (the
// course's practice task 3, VSM setup). Edit both functions, then: shadowlab check --lab 3
// What each call does and why: this lab's text (README.md, "The moments target in OpenGL").
#include "labs/03_vsm_setup/gl_setup.h"

namespace shadowlab {

MomentsTarget create_moments_target(int size, GLenum moments_format) {
  MomentsTarget target;
  target.size = size;
  // TODO: the moments, the depth buffer of their pass and the framebuffer that draws into both.
  //   1. A colour texture (glGenTextures, glBindTexture(GL_TEXTURE_2D, ...)) with storage for size x size
  //      moments: glTexImage2D with the internal format moments_format (GL_RG32F), format GL_RG, GL_FLOAT.
  //   2. Its filtering: the lit pass reads the moments filtered between texels (GL_TEXTURE_MIN_FILTER,
  //      GL_TEXTURE_MAG_FILTER).
  //   3. Its wrap: what a lookup outside [0, 1] reads (GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T): never the
  //      other side of the map.
  //   4. A renderbuffer (glGenRenderbuffers, glBindRenderbuffer, glRenderbufferStorage) of size x size
  //      GL_DEPTH_COMPONENT24 depths: the moments pass keeps the nearest surface with the depth test.
  //   5. A framebuffer (glGenFramebuffers, glBindFramebuffer) with the texture as GL_COLOR_ATTACHMENT0
  //      (glFramebufferTexture2D) and the renderbuffer as GL_DEPTH_ATTACHMENT (glFramebufferRenderbuffer).
  //   6. Bind framebuffer 0 again before returning.
  (void)moments_format;
  glGenTextures(1, &target.moments_texture);
  return target;
}

void begin_moments_pass(const MomentsTarget& target) {
  // TODO: make the target the framebuffer drawn into, cover the whole map with the viewport, and clear
  // its colour to (1, 1, 0, 0) (glClearColor) and its depth to the far plane (1), both in one glClear.
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
}

}  // namespace shadowlab
