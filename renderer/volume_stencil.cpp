// The solution of lab 9's GL exercise, and the renderer's own code path (renderer/volume_stencil.h).
#include "renderer/volume_stencil.h"

namespace shadowlab {

void stencil_pass(bool z_fail, const std::function<void()>& draw_volumes) {
  // The counts start at 0 (lit) in every pixel: last frame's would be added to.
  glEnable(GL_STENCIL_TEST);
  glStencilMask(0xFF);  // a clear writes only the stencil bits the mask lets through
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  // Only the stencil changes: no colour, no depth writes, but the depth test against the scene's depth.
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // both sides in one draw, each with its own stencil operation
  glStencilFunc(GL_ALWAYS, 0, 0xFF);  // every fragment counts
  if (z_fail) {
    // Carmack's reverse: count the faces behind the surface, out to infinity. The far caps' points at
    // infinity land on the far plane, in floating point a hair beyond: clamped, not clipped.
    glEnable(GL_DEPTH_CLAMP);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
  } else {
    // Count the faces between the eye and the surface: entering a volume +1, leaving it -1. Wrapping, so
    // that a -1 drawn before its +1 does not stick at 0.
    glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  }
  draw_volumes();
  glDisable(GL_DEPTH_CLAMP);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
}

void begin_additive_lit_pass() {
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_EQUAL);  // exactly the surfaces the ambient pass kept (the same vertices, invariant)
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xFF);  // a count of 0: inside no volume, lit
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);  // the light's share added to the ambient colour already there
}

}  // namespace shadowlab
