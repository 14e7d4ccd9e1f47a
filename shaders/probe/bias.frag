#version 330 core
// Grading probe (grading/probe.h): runs a lab's shadow_bias(n_dot_l) on chosen inputs, one fragment per
// case, under the uniforms the check sets. Input per case: u_probe_in0.x = n . l.
#include "lab/bias.glsl"

uniform sampler2D u_probe_in0;

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  o_result = vec4(shadow_bias(a.x), 0.0, 0.0, 1.0);
}
