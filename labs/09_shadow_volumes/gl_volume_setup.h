// Lab 9's GL exercise: the stencil and blend state of the counting pass (z-pass and z-fail) and of the
// additive lit pass, written with real OpenGL calls in gl_volume_stencil.cpp (lecture 9's passes 2 and 3).
// The two functions are the renderer's own (renderer/volume_stencil.h), whose file
// renderer/volume_stencil.cpp is the solution.
//
// Graded in a program of its own (grading/cpp_exercise.h, `renders`): gl_volume_stencil_host.cpp makes a
// headless OpenGL context inside the sandbox, runs the three passes over a tiny known scene through the
// student's functions and answers with the state they left and the stencil counts and colours they gave
// (a VolumeState), which the lab's check turns into named criteria.
#pragma once

#include "renderer/volume_stencil.h"

namespace shadowlab {

// The scene: one pixel per column, a receiver at NDC depth kReceiverZ in every column, and in front of
// it or behind it the faces of the volumes, each a quad over its column at an NDC depth, drawn in this
// order. A front face is counter-clockwise on screen, a back face clockwise. kFarCapZ lies a hair beyond
// the far plane, as a far cap at infinity may in floating point (it is clipped unless depth is clamped).
inline constexpr int kVolumeColumns = 8;
inline constexpr float kReceiverZ = 0.5f;
inline constexpr float kFarCapZ = 1.001f;
struct VolumeFace {
  int column;
  float z;
  bool front;
};
inline constexpr VolumeFace kVolumeFaces[] = {
    // 0: open, no volume.
    // 1 and 2: a volume between the eye and the receiver, its -1 face drawn first in z-pass (1) and its
    // +1 face first (2): counts that would go below 0 in one order whichever sign a face counts.
    {1, 0.0f, false}, {1, -0.5f, true}, {2, -0.5f, true}, {2, 0.0f, false},
    // 3: the receiver inside a volume closed by a far cap beyond the far plane.
    {3, 0.0f, true}, {3, kFarCapZ, false},
    // 4 and 5: a volume behind the receiver, front face first (4) and back face first (5).
    {4, 0.7f, true}, {4, 0.9f, false}, {5, 0.9f, false}, {5, 0.7f, true},
    // 6: the eye inside a volume: its front face is behind the eye, only the back face is drawn.
    {6, 0.9f, false},
    // 7: the receiver inside two overlapping volumes, back faces first.
    {7, 0.8f, false}, {7, kFarCapZ, false}, {7, -0.5f, true}, {7, 0.0f, true}};
// How many volumes hold each column's receiver: 0 is lit.
inline constexpr int kInsideVolumes[kVolumeColumns] = {0, 0, 0, 1, 0, 0, 1, 2};
// z-pass counts only from outside every volume: the columns it is graded on (not 6).
inline constexpr bool kZPassGraded[kVolumeColumns] = {true, true, true, true, true, true, false, true};

// The colours the host draws: the ambient pass, then the light's share the lit pass adds (red channel).
inline constexpr float kAmbientShare = 0.25f;
inline constexpr float kLightShare = 0.5f;
// The stencil value the host leaves before the counting pass (a last frame's counts).
inline constexpr int kStainStencil = 3;

// One request: the counting method.
struct VolumeCall {
  int z_fail = 0;
};

// What the student's functions left, read back with glGet* queries and glReadPixels.
struct VolumeState {
  int gl_error_after_pass = 0, gl_error_after_lit = 0;  // the first glGetError after each function
  // In the counting pass, read in the first call of draw_volumes (draws: how many calls):
  int draws = 0;
  int stencil_test = 0, stencil_func = 0, stencil_ref = 0, stencil_value_mask = 0, stencil_writemask = 0;
  int front_ops[3] = {0, 0, 0};  // GL_STENCIL_FAIL, _PASS_DEPTH_FAIL, _PASS_DEPTH_PASS
  int back_ops[3] = {0, 0, 0};   // GL_STENCIL_BACK_FAIL, ...
  int non_wrapping_ops = 0;      // GL_INCR or GL_DECR in any slot of either side, in any call
  int colour_writemask[4] = {0, 0, 0, 0};
  int depth_writemask = 0, depth_test = 0, depth_func = 0, depth_clamp = 0, cull_face = 0;
  int stencil_at_first_draw = -1;  // column 0's stencil when draw_volumes is first called (cleared: 0)
  // After stencil_pass returned:
  int colour_writemask_after[4] = {0, 0, 0, 0};
  int depth_clamp_after = 0, cull_face_after = 0;
  int counts[kVolumeColumns] = {};  // the stencil of each column
  // After begin_additive_lit_pass:
  int lit_stencil_test = 0, lit_stencil_func = 0, lit_stencil_ref = 0, lit_stencil_value_mask = 0;
  int lit_depth_test = 0, lit_depth_func = 0, lit_depth_writemask = 0;
  int blend = 0, blend_src_rgb = 0, blend_dst_rgb = 0;
  // The picture: each column's red channel (0-255) after the lit pass.
  int red[kVolumeColumns] = {};
};

}  // namespace shadowlab
