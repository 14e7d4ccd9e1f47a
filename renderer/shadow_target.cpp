// The solution of lab 0's GL exercise, and the renderer's own code path (renderer/shadow_target.h).
#include "renderer/shadow_target.h"

namespace shadowlab {

ShadowTarget create_shadow_target(int size, GLenum depth_format) {
  ShadowTarget target;
  target.size = size;
  // 1. The map: a depth texture (a depth format and GL_DEPTH_COMPONENT data) with no data yet.
  glGenTextures(1, &target.depth_texture);
  glBindTexture(GL_TEXTURE_2D, target.depth_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(depth_format), size, size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
  // 2. One comparison reads one texel: nearest, not linear (interpolated depths are no surface's).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  // 3. Outside [0, 1] the map must not repeat: clamped, the edge texels answer (the shader's own range
  // test returns lit there).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  // 4. The framebuffer: the texture as its depth attachment, and no colour buffer to draw or read.
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
  glViewport(0, 0, target.size, target.size);  // the whole map, not the window
  glDepthMask(GL_TRUE);                        // a clear writes only where depth writes are on
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);                // last frame's depths would hide this frame's
}

}  // namespace shadowlab
