// Lab 9's GL exercise: the stencil and blend state of the counting pass (z-pass and z-fail) and of the
// additive lit pass, in OpenGL (lecture 9's passes 2 and 3). Edit both functions, then:
// shadowlab check --lab 9
// What each call does and why: this lab's text (README.md, "The stencil passes in OpenGL").
#include "labs/09_shadow_volumes/gl_volume_setup.h"

namespace shadowlab {

void stencil_pass(bool z_fail, const std::function<void()>& draw_volumes) {
  // TODO: count the volumes into the stencil buffer, over the depth the ambient pass left.
  //   1. The counts start at 0 in every pixel: clear the stencil (glClearStencil, glClear), with every
  //      stencil bit writable (glStencilMask).
  //   2. Only the stencil may change: colour writes off (glColorMask) and depth writes off (glDepthMask),
  //      but the depth test kept on (glEnable(GL_DEPTH_TEST), glDepthFunc) against the scene's depth.
  //   3. Every fragment of a volume counts: the stencil test on, passing always (glStencilFunc).
  //   4. Front and back faces count in opposite directions, in one draw (glStencilOpSeparate; culling
  //      off) or in two (glStencilOp with glCullFace), and the counts wrap (GL_INCR_WRAP, GL_DECR_WRAP):
  //      z-pass: where the depth test passes, front faces +1, back faces -1;
  //      z-fail: where it fails, back faces +1, front faces -1, with GL_DEPTH_CLAMP on, so that the far
  //      caps (at infinity: a hair beyond the far plane in floating point) are kept.
  //   5. draw_volumes(), then colour and depth writes on again, depth clamping and culling off.
  (void)z_fail;
  draw_volumes();
}

void begin_additive_lit_pass() {
  // TODO: the lit pass draws the scene again where the stencil count is 0 (glStencilFunc), only on the
  // surfaces the ambient pass kept (glDepthFunc, no depth writes), and adds its light to the ambient
  // colour already there (glEnable(GL_BLEND), glBlendFunc).
}

}  // namespace shadowlab
