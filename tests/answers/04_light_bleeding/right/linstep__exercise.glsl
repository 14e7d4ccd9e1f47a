// right: the remap as a linstep(delta, 1, p) helper (Lauritzen's name for it)
// expect: variant
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)", 0.125 by default

// Lauritzen's linstep: 0 below lo, 1 above hi, linear between.
float linstep(float lo, float hi, float v) { return clamp((v - lo) / (hi - lo), 0.0, 1.0); }

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  float p = chebyshev_upper_bound(moments, s.z - shadow_bias(n_dot_l));
  return linstep(u_bleed_delta, 1.0, p);
}
