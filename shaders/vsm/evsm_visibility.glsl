// The EVSM test (lab 13): the filtered moments of both warped depths, the minimum variance taken to each
// warp's units, then the student's two-sided bound evsm_bound ("lab/warp.glsl") at the receiver's warped
// (and biased) depths, then VSM's light-bleeding remap. With u_warp_exponent = 0 it is the VSM test
// (shaders/vsm/visibility.glsl) on the first two moments. 1 lit, 0 shadowed, soft in between.
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"
#include "lab/warp.glsl"

uniform float u_bleed_delta;             // slider "Light-bleeding cut (delta)"
uniform float u_warp_exponent;           // c+, clamped for the format; 0: no warp
uniform float u_warp_negative_exponent;  // c-, clamped for the format

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec4 moments = texture(u_shadow_map, s.xy);
  float z = s.z - shadow_bias(n_dot_l);
  vec2 c = vec2(u_warp_exponent, u_warp_negative_exponent);
  float p;
  if (c.x > 0.0) {
    // The minimum variance is a depth variance (slider "Minimum variance"); in warped units it scales with
    // the warp's slope squared at the occluders' mean, (dw/dz)^2 = (c mu)^2 for both warps. (At the
    // receiver's, (c w)^2, it would light every shadow by about min_variance c^2: 0.35 % at c = 42,
    // measured.) Raising E[w^2] to mu^2 + that floor applies it before the bound.
    moments.y = max(moments.y, moments.x * moments.x * (1.0 + u_min_variance * c.x * c.x));
    moments.w = max(moments.w, moments.z * moments.z * (1.0 + u_min_variance * c.y * c.y));
    p = evsm_bound(moments, evsm_warp(z, c));
  } else {
    p = chebyshev_upper_bound(moments.xy, z);
  }
  return clamp((p - u_bleed_delta) / (1.0 - u_bleed_delta), 0.0, 1.0);  // as in shaders/vsm/visibility.glsl
}
