#version 330 core
// Moments pass (variance shadow maps): instead of letting the depth test store one depth per texel,
// write the first two moments of the depth distribution into a colour attachment (RG32F or RG16F).
// Colour can be filtered linearly and blurred, a depth buffer cannot: that is the point of VSM. The
// depth test still runs, against the pass's own depth renderbuffer, so each texel keeps the nearest
// surface. What the moments are is "lab/moments.glsl"'s job (lab 3).
// An alpha-tested caster (the ALPHA_MASK variant) discards where the view does: after the moments, whose
// slope term takes derivatives across the whole quad of fragments.
#include "lab/moments.glsl"
#include "shadow/alpha_mask.glsl"

// EVSM's moments (lab 13) are four: its "lab/moments.glsl" defines MOMENTS_TYPE vec4.
#ifndef MOMENTS_TYPE
#define MOMENTS_TYPE vec2
#endif
layout(location = 0) out MOMENTS_TYPE o_moments;

void main() {
  o_moments = shadow_moments(gl_FragCoord.z);
  alpha_test();
}
