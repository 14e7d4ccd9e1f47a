// wrong: the viewport left at the window's size (no glViewport in the pass)
// expect: skipped-half
// fails: gl_setup.viewport_error
#include "labs/00_basic_shadow_map/gl_setup.h"

namespace shadowlab {

ShadowTarget create_shadow_target(int size, GLenum depth_format) {
  ShadowTarget target;
  target.size = size;
  glGenTextures(1, &target.depth_texture);
  glBindTexture(GL_TEXTURE_2D, target.depth_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, depth_format, size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, target.depth_texture, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

void begin_shadow_pass(const ShadowTarget& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glClear(GL_DEPTH_BUFFER_BIT);
}

}  // namespace shadowlab
