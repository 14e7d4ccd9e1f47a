// wrong: only the remap; step 1 (subtract the bias from z) skipped
// expect: skipped-half
// fails: probe.bias_mismatch
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)", 0.125 by default

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  float p = chebyshev_upper_bound(moments, s.z);
  return clamp((p - u_bleed_delta) / (1.0 - u_bleed_delta), 0.0, 1.0);
}
