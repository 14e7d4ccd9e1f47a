#version 330 core
// Grading probe (grading/probe.h): runs lab 13's evsm_bound(moments, w) on chosen inputs, one fragment per
// case. Input per case: u_probe_in0 = (E[w+], E[w+^2], E[w-], E[w-^2]), u_probe_in1 = (w+, w-, unused, unused).
#include "lab/warp.glsl"

uniform sampler2D u_probe_in0;
uniform sampler2D u_probe_in1;

out vec4 o_result;

void main() {
  vec4 m = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  vec4 w = texelFetch(u_probe_in1, ivec2(gl_FragCoord.xy), 0);
  o_result = vec4(evsm_bound(m, w.xy), 0.0, 0.0, 1.0);
}
