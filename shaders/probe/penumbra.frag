#version 330 core
// Grading probe (grading/probe.h): runs lab 16's penumbra_width(receiver_depth, blocker_depth, light_size)
// on chosen inputs, one fragment per case. Input per case: u_probe_in0 = (receiver, blocker, size, unused).
#include "lab/penumbra.glsl"

uniform sampler2D u_probe_in0;

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  o_result = vec4(penumbra_width(a.x, a.y, a.z), 0.0, 0.0, 1.0);
}
