// right: the calls in another order, the stencil cleared with glClearBufferiv, the faces' state set with
// the per-face calls for both sides, and the lit test written "0 >= count" (GL_GEQUAL: only 0 passes)
// expect: variant
#include "labs/09_shadow_volumes/gl_volume_setup.h"

namespace shadowlab {

void stencil_pass(bool z_fail, const std::function<void()>& draw_volumes) {
  glDepthMask(GL_FALSE);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDisable(GL_CULL_FACE);
  glStencilMaskSeparate(GL_FRONT_AND_BACK, 0xFF);
  const GLint zero = 0;
  glClearBufferiv(GL_STENCIL, 0, &zero);
  glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_ALWAYS, 0, 0xFF);
  const GLenum count_up = z_fail ? GL_BACK : GL_FRONT, count_down = z_fail ? GL_FRONT : GL_BACK;
  if (z_fail) {
    glStencilOpSeparate(count_up, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    glStencilOpSeparate(count_down, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    glEnable(GL_DEPTH_CLAMP);
  } else {
    glStencilOpSeparate(count_up, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    glStencilOpSeparate(count_down, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  }
  glEnable(GL_STENCIL_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_DEPTH_TEST);
  draw_volumes();
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_DEPTH_CLAMP);
}

void begin_additive_lit_pass() {
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_BLEND);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_GEQUAL, 0, 0xFF);
  glEnable(GL_STENCIL_TEST);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_DEPTH_TEST);
}

}  // namespace shadowlab
