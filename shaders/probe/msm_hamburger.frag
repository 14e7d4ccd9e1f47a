#version 330 core
// Grading probe (grading/probe.h): runs lab 14's msm_hamburger(b, z) on chosen inputs, one fragment per
// case. Input per case: u_probe_in0 = the biased moments b, u_probe_in1 = (z, unused, unused, unused).
#include "lab/hamburger.glsl"

uniform sampler2D u_probe_in0;
uniform sampler2D u_probe_in1;

out vec4 o_result;

void main() {
  vec4 b = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  vec4 z = texelFetch(u_probe_in1, ivec2(gl_FragCoord.xy), 0);
  o_result = vec4(msm_hamburger(b, z.x), 0.0, 0.0, 1.0);
}
