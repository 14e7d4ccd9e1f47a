// right: GL_RGBA32F (the moments in .rg, two channels unused): the same 32-bit moments, twice the memory
// expect: variant
#include "labs/03_vsm_setup/gl_setup.h"

namespace shadowlab {

MomentsTarget create_moments_target(int size, GLenum moments_format) {
  MomentsTarget target;
  target.size = size;
  glGenTextures(1, &target.moments_texture);
  glBindTexture(GL_TEXTURE_2D, target.moments_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size, size, 0, GL_RGBA, GL_FLOAT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenRenderbuffers(1, &target.depth_renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, target.depth_renderbuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  glGenFramebuffers(1, &target.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.moments_texture, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target.depth_renderbuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return target;
}

void begin_moments_pass(const MomentsTarget& target) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
  glViewport(0, 0, target.size, target.size);
  glClearColor(1.0f, 1.0f, 0.0f, 0.0f);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

}  // namespace shadowlab
