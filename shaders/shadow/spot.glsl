// The spot light's shadow test (lab 7's solution). A perspective map stores depth that is NOT linear in
// distance: d = f/(f-n) * (1 - n/z) crowds most of [0, 1] near the light, so a constant bias in d is a
// tiny distance near the light and a huge one far away. Compare linear distances along the light's axis
// instead, with a bias in world units that grows with a texel's footprint (distance x texel angle) and
// with the slope. 1 lit, 0 shadowed.
uniform float u_light_near;   // the fitted near and far planes of the spot's projection
uniform float u_light_far;
uniform float u_texel_angle;  // world size of one texel per unit of distance: 2 tan(cone) / size
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)
#include "shadow/slope.glsl"

// One texel's worth of distance is always subtracted: the stored depth belongs to the texel's centre.
const float CONSTANT_TEXELS = 1.0;

// Window depth [0, 1] back to the distance along the light's axis (inverting the perspective matrix).
float linear_depth(float d) {
  float z_ndc = d * 2.0 - 1.0;
  return 2.0 * u_light_near * u_light_far / (u_light_far + u_light_near - z_ndc * (u_light_far - u_light_near));
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float stored = linear_depth(texture(u_shadow_map, s.xy).r);
  float mine = linear_depth(s.z);
  float texel_world = mine * u_texel_angle;
  float bias = texel_world * (CONSTANT_TEXELS + u_bias_slope * shadow_tan_incidence(n_dot_l));
  return mine - bias > stored ? 0.0 : 1.0;
}
