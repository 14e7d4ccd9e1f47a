// Lab 0's GL exercise: the depth framebuffer of the shadow map and the start of its pass, written with
// real OpenGL calls in gl_shadow_target.cpp (the course's first lab sheet). The two functions are the
// renderer's own (renderer/shadow_target.h), whose file renderer/shadow_target.cpp is the solution.
//
// Graded in a program of its own (grading/cpp_exercise.h, `renders`): gl_shadow_target_host.cpp makes a
// headless OpenGL context inside the sandbox, calls the student's functions and answers with the state
// they left (a TargetState), which the lab's check turns into named criteria.
#pragma once

#include "renderer/shadow_target.h"

namespace shadowlab {

// One request: the map's size, and the window's size the viewport holds before the pass begins.
struct TargetCall {
  int size = 0;
  int window_width = 0, window_height = 0;
};

// What the student's functions left, read back with glGet* queries (0 where there was nothing to ask).
struct TargetState {
  // After create_shadow_target:
  int gl_error_after_create = 0;   // the first glGetError
  int is_framebuffer = 0, is_texture = 0;  // glIsFramebuffer(target.framebuffer), glIsTexture(target.depth_texture)
  int size = 0;                    // target.size as returned
  int framebuffer = 0, texture = 0;  // target.framebuffer, target.depth_texture as returned
  int status = 0;                  // glCheckFramebufferStatus with target.framebuffer bound
  int depth_attachment_type = 0, depth_attachment_name = 0;  // GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE / _NAME
  int colour_attachment_type = 0;  // of GL_COLOR_ATTACHMENT0
  int draw_buffer = 0, read_buffer = 0;  // GL_DRAW_BUFFER, GL_READ_BUFFER with the framebuffer bound
  int internal_format = 0, width = 0, height = 0, depth_bits = 0;  // the texture's level 0
  int min_filter = 0, mag_filter = 0, wrap_s = 0, wrap_t = 0;
  float border[4] = {0, 0, 0, 0};  // GL_TEXTURE_BORDER_COLOR
  // After begin_shadow_pass (the map's depths were set to kStainDepth before it, as a last frame's):
  int gl_error_after_begin = 0;
  int pass_framebuffer = 0;  // GL_DRAW_FRAMEBUFFER_BINDING
  int viewport[4] = {0, 0, 0, 0};
  float depth_min = -1, depth_max = -1;  // over the whole map; -1: not readable (incomplete)
  // What a lit pass then reads (kProbeUv): the host draws an occluder at depth kOccluderDepth over the
  // map's lower left quarter through the state begin_shadow_pass left, and samples the map with
  // texture() at each point; -1: not run (the framebuffer is incomplete).
  float probe_reads[5] = {-1, -1, -1, -1, -1};  // kGlProbePoints
};

// The occluder's depth, and where the probe reads: under it, in the open, beyond the right edge beside it
// and beyond the top edge above it (a map that repeats reads the occluder there), and on its right edge
// (between an occluded and an open texel: nearest reads either, linear a depth no surface has).
inline constexpr float kOccluderDepth = 0.3f;
inline constexpr int kGlProbePoints = 5;
inline constexpr float kProbeUv[kGlProbePoints][2] = {{0.25f, 0.25f}, {0.75f, 0.75f}, {1.1f, 0.25f}, {0.25f, 1.1f}, {0.5f, 0.25f}};
static_assert(sizeof(TargetState::probe_reads) == kGlProbePoints * sizeof(float), "one read per probe point");

// The depth the host writes into the map before begin_shadow_pass: a pass that does not clear keeps it.
inline constexpr float kStainDepth = 0.25f;

}  // namespace shadowlab
