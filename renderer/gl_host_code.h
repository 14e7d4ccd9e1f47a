// The host code of the labs' OpenGL exercises, which the renderer calls through these pointers: its own
// functions (the defaults, which are the exercises' solutions: lab 0's depth framebuffer, lab 3's moments
// target, lab 5's blur passes, lab 9's stencil state), or, in the window on the student's own machine,
// those of the student's edited file, built into a shared library and loaded into the window's process
// (grading/live_gl.h). Features::gl_host hands them to the passes; a pass whose code changes makes its
// targets again.
#pragma once

#include <functional>

#include "renderer/blur_passes.h"
#include "renderer/moments_target.h"
#include "renderer/shadow_target.h"
#include "renderer/volume_stencil.h"

namespace shadowlab {

struct GlHostCode {
  ShadowTarget (*create_shadow_target)(int size, GLenum depth_format) = &shadowlab::create_shadow_target;
  void (*begin_shadow_pass)(const ShadowTarget& target) = &shadowlab::begin_shadow_pass;
  MomentsTarget (*create_moments_target)(int size, GLenum moments_format) = &shadowlab::create_moments_target;
  void (*begin_moments_pass)(const MomentsTarget& target) = &shadowlab::begin_moments_pass;
  BlurTarget (*create_blur_target)(int size, GLenum internal_format) = &shadowlab::create_blur_target;
  void (*run_blur_passes)(const BlurJob& job) = &shadowlab::run_blur_passes;
  void (*stencil_pass)(bool z_fail, const std::function<void()>& draw_volumes) = &shadowlab::stencil_pass;
  void (*begin_additive_lit_pass)() = &shadowlab::begin_additive_lit_pass;

  bool operator==(const GlHostCode&) const = default;
  // Whether the targets these functions make are the renderer's own (an incomplete framebuffer is then a
  // bug of ours, thrown; a student's is said on stderr and drawn as it is: the picture shows the mistake).
  bool own_shadow_target() const {
    return create_shadow_target == &shadowlab::create_shadow_target && begin_shadow_pass == &shadowlab::begin_shadow_pass;
  }
  bool own_moments_target() const {
    return create_moments_target == &shadowlab::create_moments_target &&
           begin_moments_pass == &shadowlab::begin_moments_pass && create_blur_target == &shadowlab::create_blur_target;
  }
};

// Says on stderr that a student's target is incomplete (the framebuffer bound): `what` names it.
void say_incomplete_target(const char* what, const char* function);

}  // namespace shadowlab
