// Lab 3's GL exercise: the render target of variance shadow maps and the start of its pass, written with
// real OpenGL calls in gl_moments_target.cpp (the course's practice task 3, VSM setup). The two functions
// are the renderer's own (renderer/moments_target.h), whose file renderer/moments_target.cpp is the
// solution.
//
// Graded in a program of its own (grading/cpp_exercise.h, `renders`): gl_moments_target_host.cpp makes a
// headless OpenGL context inside the sandbox, calls the student's functions and answers with the state
// they left (a MomentsState; its constants in moments_probe), which the lab's check turns into named criteria.
#pragma once

#include "renderer/moments_target.h"

namespace shadowlab {

// One request: the map's size, and the window's size the viewport holds before the pass begins.
struct MomentsCall {
  int size = 0;
  int window_width = 0, window_height = 0;
};

// What the student's functions left, read back with glGet* queries (0 where there was nothing to ask).
struct MomentsState {
  // After create_moments_target:
  int gl_error_after_create = 0;  // the first glGetError
  int is_framebuffer = 0, is_texture = 0, is_renderbuffer = 0;  // glIs* of the three names returned
  int size = 0;                                                 // target.size as returned
  int framebuffer = 0, texture = 0, renderbuffer = 0;           // the three names as returned
  int status = 0;  // glCheckFramebufferStatus with target.framebuffer bound
  int colour_attachment_type = 0, colour_attachment_name = 0;  // of GL_COLOR_ATTACHMENT0
  int depth_attachment_type = 0, depth_attachment_name = 0;    // of GL_DEPTH_ATTACHMENT
  int depth_bits = 0;  // GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE of the depth attachment
  int renderbuffer_format = 0;  // GL_RENDERBUFFER_INTERNAL_FORMAT of target.depth_renderbuffer
  int internal_format = 0, width = 0, height = 0;  // the moments texture's level 0
  int red_bits = 0, green_bits = 0, red_type = 0;  // GL_TEXTURE_RED_SIZE, _GREEN_SIZE, GL_TEXTURE_RED_TYPE
  int min_filter = 0, mag_filter = 0, wrap_s = 0, wrap_t = 0;
  float border[4] = {0, 0, 0, 0};  // GL_TEXTURE_BORDER_COLOR
  // After begin_moments_pass (the moments were set to kStainMoments and the depths to kStainDepth before
  // it, as a last frame's):
  int gl_error_after_begin = 0;
  int pass_framebuffer = 0;  // GL_DRAW_FRAMEBUFFER_BINDING
  int viewport[4] = {0, 0, 0, 0};
  // The largest |E[z] - 1| and |E[z^2] - 1| over the map, and the smallest depth; -1: not readable.
  float moments_off_clear = -1, depth_min = -1;
  // What a lit pass then reads (kProbeUv): through the state begin_moments_pass left, the host draws the
  // moments (z, z^2) of a near occluder over the map's lower left quarter, then of a far one over its left
  // half (the depth test keeps the near one), samples the map with texture() at each point and computes
  // Chebyshev's bound for a receiver at kReceiverDepth; -1: not run (the framebuffer is incomplete).
  float probe_moments[5][2] = {{-1, -1}, {-1, -1}, {-1, -1}, {-1, -1}, {-1, -1}};
  float probe_bounds[5] = {-1, -1, -1, -1, -1};  // kGlProbePoints
};

// The probe's constants, in a namespace of their own: lab 0's gl_setup.h has constants of the same names
// in the same library.
namespace moments_probe {

// The occluders' depths (window z), and where the probe reads: under the near occluder (a receiver just
// behind it: there the variance the format keeps decides the bound), in the open, beyond the right edge
// beside the open lower right quarter and beyond the top edge above the far occluder (a map that repeats
// reads the near occluder there), and on the near occluder's right edge (a filtered map reads the mean of
// its moments and the clear value's, nearest filtering one or the other).
inline constexpr float kNearDepth = 0.3f, kFarDepth = 0.7f;
inline constexpr int kGlProbePoints = 5;
inline constexpr float kProbeUv[kGlProbePoints][2] = {{0.25f, 0.25f}, {0.75f, 0.75f}, {1.1f, 0.25f}, {0.25f, 1.1f}, {0.5f, 0.25f}};
inline constexpr float kReceiverDepth[] = {0.32f, 0.5f, 0.5f, 0.5f, 0.8f};
static_assert(sizeof kReceiverDepth == kGlProbePoints * sizeof(float), "one receiver per probe point");
// The probe's minimum variance (the lit pass's u_min_variance): the bound 0.02 behind the near occluder
// is 1e-4 / (1e-4 + 0.02^2) = 0.2 where the map keeps the variance 0.
inline constexpr float kProbeMinVariance = 1e-4f;
static_assert(sizeof(MomentsState::probe_bounds) == kGlProbePoints * sizeof(float), "one bound per probe point");

// What the host writes into the map before begin_moments_pass: a pass that does not clear keeps it.
inline constexpr float kStainMoments[4] = {0.25f, 0.0625f, 0.0f, 0.0f};
inline constexpr float kStainDepth = 0.25f;

}  // namespace moments_probe

}  // namespace shadowlab
