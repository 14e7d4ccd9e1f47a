// wrong: calls the renderer's shadow_coords() and outside_shadow_map() instead of writing the bias matrix
// expect: borrowed-helper
// fails: compile_error
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);  // hard.glsl does it this way
  if (outside_shadow_map(s)) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
