// wrong: only the bias; step 2 (the light-bleeding remap) skipped
// expect: skipped-half
// fails: probe.remap_mismatch *.bleeding_ratio_to_unfixed
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)", 0.125 by default

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  float p = chebyshev_upper_bound(moments, s.z - shadow_bias(n_dot_l));
  return p;
}
