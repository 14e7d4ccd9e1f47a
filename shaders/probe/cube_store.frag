#version 330 core
// Grading probe (grading/probe.h): runs a point-light lab's value_to_store(world_position), what the shadow
// pass writes into its faces, on chosen points, one fragment per case. Input per case: u_probe_in0.xyz =
// the world position. v_world_position is set to it too, for a function that reads the varying.
uniform vec3 u_light_position;
vec3 v_world_position;

#include "lab/cube_store.glsl"

uniform sampler2D u_probe_in0;

out vec4 o_result;

void main() {
  v_world_position = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0).xyz;
  o_result = vec4(value_to_store(v_world_position), 0.0, 0.0, 1.0);
}
