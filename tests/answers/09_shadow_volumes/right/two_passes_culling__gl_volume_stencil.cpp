// right: two passes with face culling and glStencilOp (Heidmann 1991's way), culling off again after
// expect: variant
#include "labs/09_shadow_volumes/gl_volume_setup.h"

namespace shadowlab {

void stencil_pass(bool z_fail, const std::function<void()>& draw_volumes) {
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xFF);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glStencilFunc(GL_ALWAYS, 0, 0xFF);
  if (z_fail) glEnable(GL_DEPTH_CLAMP);
  glEnable(GL_CULL_FACE);
  // Back faces first: z-fail +1 where the depth test fails, z-pass -1 where it passes.
  glCullFace(GL_FRONT);
  if (z_fail)
    glStencilOp(GL_KEEP, GL_INCR_WRAP, GL_KEEP);
  else
    glStencilOp(GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  draw_volumes();
  // Then front faces: z-fail -1 where it fails, z-pass +1 where it passes.
  glCullFace(GL_BACK);
  if (z_fail)
    glStencilOp(GL_KEEP, GL_DECR_WRAP, GL_KEEP);
  else
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  draw_volumes();
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_CLAMP);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
}

void begin_additive_lit_pass() {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_EQUAL);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
}

}  // namespace shadowlab
