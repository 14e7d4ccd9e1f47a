// The render target of variance shadow maps and the start of its pass: the OpenGL side of the course's
// practice task 3 (VSM setup). renderer/moments_target.cpp is the renderer's own code (MomentsPass draws
// every moments map through it) and the solution of lab 3's GL exercise
// (labs/03_vsm_setup/gl_moments_target.cpp), which a student writes with the same two functions: the
// renderer and the answer cannot drift apart.
#pragma once

#include "renderer/gl.h"

namespace shadowlab {

struct MomentsTarget {
  GLuint framebuffer = 0;         // the framebuffer object the moments pass draws into
  GLuint moments_texture = 0;     // its colour attachment 0, which the lit pass reads (E[z], E[z^2])
  GLuint depth_renderbuffer = 0;  // its depth attachment: the depth test of the moments pass, never read
  int size = 0;                   // width and height in texels
};

// A framebuffer with a size x size colour texture in `moments_format` (GL_RG32F; the renderer also asks
// for GL_RG16F and, for EVSM's four moments, GL_RGBA32F and GL_RGBA16F) as GL_COLOR_ATTACHMENT0, read
// with linear filtering and clamped outside [0, 1], and a GL_DEPTH_COMPONENT24 renderbuffer as its depth
// attachment. Leaves framebuffer 0 bound. The caller owns the three objects.
MomentsTarget create_moments_target(int size, GLenum moments_format = GL_RG32F);

// Binds the target, sets the viewport to the whole map, clears the moments to (1, 1, 0, 0) (the far
// plane's z and z^2: an empty texel hides nothing) and the depth to 1.
void begin_moments_pass(const MomentsTarget& target);

}  // namespace shadowlab
