// The basic shadow test: one depth comparison against the nearest texel. 1 lit, 0 shadowed.
#include "lab/bias.glsl"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
