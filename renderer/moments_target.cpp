// The solution of lab 3's GL exercise, and the renderer's own code path (renderer/moments_target.h).
#include "renderer/moments_target.h"

namespace shadowlab {

MomentsTarget create_moments_target(int size, GLenum moments_format) {
  MomentsTarget target;
  target.size = size;
  // 1. The moments: a float colour texture (z and z^2 need 32-bit floats) with no data yet.
  glGenTextures(1, &target.moments_texture);
  glBindTexture(GL_TEXTURE_2D, target.moments_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(moments_format), size, size, 0, GL_RG, GL_FLOAT, nullptr);
  // 2. Linear filtering is what VSM is for: the average of moments is still a pair of moments (the
  // average of depths compared with one depth is no surface's).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  // 3. Outside [0, 1] the map must not repeat: clamped, the edge texels answer.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  // 4. The depth test of the moments pass needs a depth buffer; it is never sampled: a renderbuffer.
  glGenRenderbuffers(1, &target.depth_renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, target.depth_renderbuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  // 5. The framebuffer: the moments as colour attachment 0 (drawn to by default), the renderbuffer as depth.
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.moments_texture, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target.depth_renderbuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

void begin_moments_pass(const MomentsTarget& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glViewport(0, 0, target.size, target.size);  // the whole map, not the window
  glClearColor(1.0f, 1.0f, 0.0f, 0.0f);        // the far plane's moments: an empty texel hides nothing
  glDepthMask(GL_TRUE);                        // a clear writes only where depth writes are on
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace shadowlab
