#version 330 core
// Moments pass of moment shadow maps: four power moments of the nearest surface's depth per texel
// into an RGBA32F attachment ("lab/msm_moments.glsl", lab 14).
// An alpha-tested caster (the ALPHA_MASK variant) discards where the view does.
#include "lab/msm_moments.glsl"
#include "shadow/alpha_mask.glsl"

layout(location = 0) out vec4 o_moments;

void main() {
  o_moments = msm_moments(gl_FragCoord.z);
  alpha_test();
}
