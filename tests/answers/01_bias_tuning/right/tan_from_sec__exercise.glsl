// right: tan(a) = sqrt(1/c^2 - 1), capped at tan(84 deg) = 9.5, bias written as texels first then converted
// expect: variant
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  const float MAX_TAN = 9.5;
  float c = max(n_dot_l, 0.001);
  float tan_a = min(sqrt(max(1.0 / (c * c) - 1.0, 0.0)), MAX_TAN);
  float texels = u_bias_slope * tan_a;
  return u_bias_constant + texels * u_texel_depth;
}
