// Lab 5's GL exercise: the host side of the separable blur of the moments (the course's two passes),
// written with real OpenGL calls in gl_blur_passes.cpp: the ping-pong target and the function that runs
// the X and Y passes through it. The two functions are the renderer's own (renderer/blur_passes.h),
// whose file renderer/blur_passes.cpp is the solution.
//
// Graded in a program of its own (grading/cpp_exercise.h, `renders`): gl_blur_passes_host.cpp makes a
// headless OpenGL context inside the sandbox, hands the student's functions a known moments texture and
// its own blur program, records the state at each draw and answers with it and the texels (a
// BlurState), which the lab's check compares with the CPU's separable Gaussian as named criteria.
#pragma once

#include "renderer/blur_passes.h"

namespace shadowlab {

// The largest map the host answers for (its replies hold every texel).
inline constexpr int kBlurMaxSize = 32;
// The draws recorded (a right answer draws twice; more are counted, not recorded).
inline constexpr int kBlurMaxDraws = 4;

// One request: the map's size, the window's size the viewport holds before the blur, the kernel.
struct BlurCall {
  int size = 0;
  int window_width = 0, window_height = 0;
  int radius = 0;
  float sigma = 0;
};

// The state at one job.draw(pass), read with glGet* (0 where there was nothing to ask).
struct BlurDraw {
  int pass = -1;                 // the argument of job.draw
  int framebuffer = 0;           // GL_DRAW_FRAMEBUFFER_BINDING
  int writes = 0;                // the texture on its GL_COLOR_ATTACHMENT0 (0: none, or the window)
  int viewport[4] = {0, 0, 0, 0};
  int depth_test = 0;            // glIsEnabled(GL_DEPTH_TEST)
  int program = 0;               // GL_CURRENT_PROGRAM
  int unit = -1;                 // the unit u_moments names
  int reads = 0;                 // the GL_TEXTURE_2D bound on that unit
  float direction[2] = {0, 0};   // u_direction
  float texel_size[2] = {0, 0};  // u_texel_size
};

// What the student's functions left.
struct BlurState {
  // After create_blur_target:
  int gl_error_after_create = 0;
  int is_framebuffer = 0, is_texture = 0;
  int size = 0, framebuffer = 0, texture = 0;  // as returned
  int status = 0;                              // glCheckFramebufferStatus with target.framebuffer bound
  int colour_attachment_type = 0, colour_attachment_name = 0;  // of GL_COLOR_ATTACHMENT0
  int internal_format = 0, width = 0, height = 0;              // the texture's level 0
  int red_type = 0, red_bits = 0;                              // GL_TEXTURE_RED_TYPE, GL_TEXTURE_RED_SIZE
  int min_filter = 0, mag_filter = 0, wrap_s = 0, wrap_t = 0;
  // During and after run_blur_passes (the host's names, to match the draws' against):
  int moments_texture = 0, moments_framebuffer = 0, program_x = 0, program_y = 0;
  int gl_error_after_run = 0;
  int draws = 0;  // job.draw calls
  BlurDraw draw[kBlurMaxDraws];
  // The moments texture after the blur (E[z], E[z^2] per texel, bottom row first), and the target's
  // texture (-1e30: not readable: incomplete, or not size x size).
  float moments[kBlurMaxSize * kBlurMaxSize * 2] = {};
  float intermediate[kBlurMaxSize * kBlurMaxSize * 2] = {};
};

// The moments the host blurs (channel 0 E[z], 1 E[z^2]): an impulse of 1 at texel (5, 9) over a step of
// 0.5 in y (rows from size * 2/3 up), and a step in x (0.2 left of the middle, 0.9 from it): with the
// step at both edges a blur that wraps reads the other side, one that runs in one direction only leaves
// the impulse a line.
inline float blur_input(int size, int x, int y, int channel) {
  if (channel == 0) return (x == 5 && y == 9 ? 1.0f : 0.0f) + (3 * y >= 2 * size ? 0.5f : 0.0f);
  return 2 * x >= size ? 0.9f : 0.2f;
}

// The depth the host leaves in the moments framebuffer's depth buffer over its left half (the moments
// pass's nearest casters; 1 elsewhere): the full-screen triangle at depth 0.5 fails a depth test there.
inline constexpr float kBlurStainDepth = 0.25f;

}  // namespace shadowlab
