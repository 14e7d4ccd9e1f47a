// The OpenGL state of stencil shadow volumes' counting and lit passes (lecture 9; Heidmann 1991, Everitt &
// Kilgard 2002). renderer/volume_stencil.cpp is the renderer's own code (ShadowVolumePass::draw_stencil
// and LitPass's additive pass call these two functions) and the solution of lab 9's GL exercise
// (labs/09_shadow_volumes/gl_volume_stencil.cpp), which a student writes with the same functions: the
// renderer and the answer cannot drift apart.
#pragma once

#include <functional>

#include "renderer/gl.h"

namespace shadowlab {

// Pass 2: counts the volumes into the bound framebuffer's stencil buffer, over the depth the ambient pass
// (1) left. Clears the stencil to 0, turns colour and depth writes off with the depth test kept on, sets
// each face side's stencil operation (z-pass: front +1 / back -1 where the depth test passes; z-fail:
// back +1 / front -1 where it fails, depth clamped so that far caps at infinity are kept), and calls
// draw_volumes (which draws every volume, both sides) once or more. Leaves colour and depth writes on,
// depth clamping and face culling off, and the stencil test on.
void stencil_pass(bool z_fail, const std::function<void()>& draw_volumes);

// Pass 3's state: the scene again, only where the stencil count is 0 and only on the surfaces the ambient
// pass kept (depth equal, no depth writes), its light added to the ambient colour (blending ONE, ONE).
// The caller draws and then ends the pass (LitPass::end: blending and the stencil test off).
void begin_additive_lit_pass();

}  // namespace shadowlab
