// The host side of the moments' separable Gaussian blur (lab 5, the course's two passes): the ping-pong
// target and the two passes through it. renderer/blur_passes.cpp is the renderer's own code
// (MomentsPass::blur_map runs every taught blur through it) and the solution of lab 5's GL exercise
// (labs/05_moment_blur/gl_blur_passes.cpp), which a student writes with the same two functions: the
// renderer and the answer cannot drift apart.
#pragma once

#include <functional>

#include "renderer/gl.h"

namespace shadowlab {

// The intermediate (ping-pong) target of the blur: a texture like the moments' and the framebuffer
// that draws into it.
struct BlurTarget {
  GLuint framebuffer = 0;  // the framebuffer object the first pass draws into
  GLuint texture = 0;      // its colour attachment, which the second pass reads
  int size = 0;            // width and height in texels
};

// A size x size texture in `internal_format` (the moments', GL_RG32F or GL_RGBA32F) with no data, read
// with linear filtering and clamped to the edge, as the framebuffer's colour attachment 0. Leaves
// framebuffer 0 bound. The caller owns both objects.
BlurTarget create_blur_target(int size, GLenum internal_format);

// One blur of the moments: where they are, the ping-pong target, and the programs of the two passes.
struct BlurJob {
  GLuint moments_texture = 0;      // the moments to blur; the lit pass reads the blurred ones here
  GLuint moments_framebuffer = 0;  // draws into moments_texture (it also has the moments pass's depth buffer)
  int size = 0;                    // of both textures
  BlurTarget target;               // the ping-pong target (create_blur_target)
  // The programs of the X and Y passes (radius and sigma already set). Each reads the texture on the
  // unit its sampler uniform "u_moments" names, the uniform "u_direction" ((1, 0) or (0, 1), in texels)
  // and "u_texel_size" (1 / size, in texture coordinates); the renderer's have their direction compiled
  // in (shaders/vsm/blur.frag, BLUR_DIRECTION) and read texels with texelFetch, so they ignore the two.
  GLuint program_x = 0, program_y = 0;
  // Draws the pass's full-screen triangle with the state set (pass: 0 the first, 1 the second). The
  // renderer times each pass here and draws twice for four moments (EVSM).
  std::function<void(int pass)> draw;
};

// The separable blur: the X pass from the moments into the target, then the Y pass from the target back
// into the moments, each over the whole map with the depth test off; the blurred moments end where the
// lit pass reads them (job.moments_texture).
void run_blur_passes(const BlurJob& job);

}  // namespace shadowlab
