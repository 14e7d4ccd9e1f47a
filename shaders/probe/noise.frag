#version 330 core
// Grading probe (grading/probe.h): runs lab 10's gradient_noise(p) or noise_octaves(p) on chosen points,
// one fragment per case. Input per case: u_probe_in0 = (p.x, p.y, 0 noise / 1 octave sum, unused).
#include "lab/noise.glsl"

uniform sampler2D u_probe_in0;

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  float v = a.z < 0.5 ? gradient_noise(a.xy) : noise_octaves(a.xy);
  o_result = vec4(v, 0.0, 0.0, 1.0);
}
