#version 330 core
// Grading probe (grading/probe.h): runs a point-light lab's face selection, stored_distance(direction), on
// chosen directions, one fragment per case, with the lit pass's includes. Input per case:
// u_probe_in0.xyz = the direction from the light.
#include "shadow/common.glsl"
#include "lab/visibility.glsl"

uniform sampler2D u_probe_in0;

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  o_result = vec4(stored_distance(a.xyz), 0.0, 0.0, 1.0);
}
