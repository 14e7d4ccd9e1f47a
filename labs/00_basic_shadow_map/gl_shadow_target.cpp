// Lab 0's GL exercise: the shadow map's depth framebuffer and the start of its pass, in OpenGL (the
// course's first lab sheet). Edit both functions, then: shadowlab check --lab 0
// What each call does and why: this lab's text (README.md, "The depth framebuffer in OpenGL").
#include "labs/00_basic_shadow_map/gl_setup.h"

namespace shadowlab {

ShadowTarget create_shadow_target(int size, GLenum depth_format) {
  ShadowTarget target;
  target.size = size;
  // TODO: the map and the framebuffer that draws into it.
  //   1. A texture (glGenTextures, glBindTexture(GL_TEXTURE_2D, ...)) with storage for size x size
  //      depths: glTexImage2D with the internal format depth_format, format GL_DEPTH_COMPONENT.
  //   2. Its filtering: one depth comparison reads one texel (GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER).
  //   3. Its wrap: what a lookup outside [0, 1] reads (GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T): never the
  //      other side of the map.
  //   4. A framebuffer (glGenFramebuffers, glBindFramebuffer) with the texture as its depth attachment
  //      (glFramebufferTexture2D), and no colour buffer to draw to or read from.
  //   5. Bind framebuffer 0 again before returning.
  (void)depth_format;
  glGenTextures(1, &target.depth_texture);
  return target;
}

void begin_shadow_pass(const ShadowTarget& target) {
  // TODO: make the target the framebuffer drawn into, cover the whole map with the viewport, and clear
  // its depth to the far plane (1).
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
}

}  // namespace shadowlab
