// wrong: inverts the projection with near and far swapped, nf / (n + d (f - n)): depth 0 maps to far, 1 to near
// expect: sign
// fails: bias.* *.shadow_error
#include "lab/bias.glsl"

uniform float u_light_near;   // the spot's fitted near and far planes (world units along its axis)
uniform float u_light_far;
uniform float u_texel_angle;  // one texel's world size per unit of distance: 2 tan(cone) / map size

// Window depth d in [0, 1] back to the distance along the light's axis: d = f/(f-n) (1 - n/z).
float linear_depth(float d) {
  return u_light_near * u_light_far / (u_light_far - d * (u_light_far - u_light_near));
}

float tan_incidence(float n_dot_l) {
  return min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  float n_ = u_light_near, f_ = u_light_far;
  float z = n_ * f_ / (n_ + s.z * (f_ - n_));
  float stored = n_ * f_ / (n_ + closest * (f_ - n_));
  float bias = z * u_texel_angle * (1.0 + u_bias_slope * tan_incidence(n_dot_l));
  return z - bias > stored ? 0.0 : 1.0;
}
