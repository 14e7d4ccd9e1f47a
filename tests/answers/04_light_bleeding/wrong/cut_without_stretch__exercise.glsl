// wrong: cuts delta off the bound, max(p - delta, 0), without stretching [delta, 1] back to [0, 1]: every lit pixel drawn at 1 - delta
// expect: partial-darkening
// fails: probe.remap_mismatch *.lit_error
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)", 0.125 by default

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  float z = s.z - shadow_bias(n_dot_l);
  float p = chebyshev_upper_bound(moments, z);
  // cut the small values that bleed
  return max(p - u_bleed_delta, 0.0);
}
