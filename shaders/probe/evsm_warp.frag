#version 330 core
// Grading probe (grading/probe.h): runs lab 13's evsm_warp(z, c) on chosen inputs, one fragment per case.
// Input per case: u_probe_in0 = (z, c+, c-, unused); u_component picks the warp returned (0: w+, 1: w-).
#include "lab/warp.glsl"

uniform sampler2D u_probe_in0;
uniform int u_component;

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  vec2 w = evsm_warp(a.x, a.yz);
  o_result = vec4(u_component == 0 ? w.x : w.y, 0.0, 0.0, 1.0);
}
