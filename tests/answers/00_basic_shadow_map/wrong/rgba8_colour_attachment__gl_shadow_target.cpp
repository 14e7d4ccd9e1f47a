// wrong: the map as an RGBA8 colour texture attached to GL_COLOR_ATTACHMENT0, as for a render target
// expect: structure
// fails: gl_setup.depth_bits gl_setup.depth_attachment_is_the_map
#include "labs/00_basic_shadow_map/gl_setup.h"

namespace shadowlab {

ShadowTarget create_shadow_target(int size, GLenum depth_format) {
  ShadowTarget target;
  target.size = size;
  glGenTextures(1, &target.depth_texture);
  glBindTexture(GL_TEXTURE_2D, target.depth_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  (void)depth_format;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.depth_texture, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

void begin_shadow_pass(const ShadowTarget& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glViewport(0, 0, target.size, target.size);
  glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace shadowlab
