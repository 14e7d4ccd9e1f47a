// right: tan(acos(n.l)) with n.l clamped to cos(84 deg), instead of sqrt(1 - c^2) / c
// expect: variant
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  float c = clamp(n_dot_l, cos(radians(84.0)), 1.0);
  return u_bias_constant + u_bias_slope * u_texel_depth * tan(acos(c));
}
