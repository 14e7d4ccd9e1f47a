// The depth framebuffer of a plain shadow map and the start of its pass: the OpenGL side of the course's
// first lab sheet. renderer/shadow_target.cpp is the renderer's own code (DepthMapPass draws every plain
// shadow map through it) and the solution of lab 0's GL exercise
// (labs/00_basic_shadow_map/gl_shadow_target.cpp), which a student writes with the same two functions:
// the renderer and the answer cannot drift apart.
#pragma once

#include "renderer/gl.h"

namespace shadowlab {

struct ShadowTarget {
  GLuint framebuffer = 0;    // the framebuffer object the depth pass draws into
  GLuint depth_texture = 0;  // its depth attachment, which the lit pass reads as the shadow map
  int size = 0;              // width and height in texels
};

// A framebuffer whose only image is a size x size depth texture in `depth_format` (GL_DEPTH_COMPONENT16,
// 24 or 32F), read with nearest filtering, clamped outside [0, 1], and no colour buffer to draw to or
// read from. Leaves framebuffer 0 bound. The caller owns both objects.
ShadowTarget create_shadow_target(int size, GLenum depth_format = GL_DEPTH_COMPONENT24);

// Binds the target, sets the viewport to the whole map and clears its depth to 1 (the far plane).
void begin_shadow_pass(const ShadowTarget& target);

}  // namespace shadowlab
