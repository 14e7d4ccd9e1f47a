#include "renderer/gl_host_code.h"

#include <cstdio>

namespace shadowlab {

void say_incomplete_target(const char* what, const char* function) {
  if (const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE)
    std::fprintf(stderr, "shadowlab: the %s framebuffer your %s made is incomplete (glCheckFramebufferStatus 0x%x): "
                 "nothing is drawn into it\n", what, function, status);
}

}  // namespace shadowlab
