// The EVSM test (lab 13): Chebyshev's bound on the filtered moments of the warped depth, at the
// receiver's warped (and biased) depth, then VSM's light-bleeding remap. With u_warp_exponent = 0 it is
// the VSM test (shaders/vsm/visibility.glsl). 1 lit, 0 shadowed, soft in between.
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"
#include "lab/warp.glsl"

uniform float u_bleed_delta;    // slider "Light-bleeding cut (delta)"
uniform float u_warp_exponent;  // c, clamped for the format; 0: no warp

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  float z = s.z - shadow_bias(n_dot_l);
  float c = u_warp_exponent;
  float w = c > 0.0 ? evsm_warp(z, c) : z;
  // The minimum variance is a depth variance (slider "Minimum variance"); in warped units it scales with
  // the warp's slope squared at the occluders' mean, (dw/dz)^2 = (c mu)^2. (At the receiver's, (c w)^2,
  // it would light every shadow by about min_variance c^2: 0.35 % at c = 42, measured.) Raising E[w^2]
  // to mu^2 + that floor applies it before chebyshev_upper_bound's own clamp.
  if (c > 0.0) moments.y = max(moments.y, moments.x * moments.x * (1.0 + u_min_variance * c * c));
  float p = chebyshev_upper_bound(moments, w);
  return clamp((p - u_bleed_delta) / (1.0 - u_bleed_delta), 0.0, 1.0);  // as in shaders/vsm/visibility.glsl
}
