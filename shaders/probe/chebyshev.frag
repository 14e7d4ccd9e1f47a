#version 330 core
// Grading probe (grading/probe.h): runs a lab's chebyshev_upper_bound(moments, z) on chosen inputs, one
// fragment per case. Input per case: u_probe_in0 = (E[z], E[z^2], z, unused).
#include "lab/chebyshev.glsl"

uniform sampler2D u_probe_in0;

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  o_result = vec4(chebyshev_upper_bound(a.xy, a.z), 0.0, 0.0, 1.0);
}
