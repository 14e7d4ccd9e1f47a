// wrong: slope as n.l / sin(a) (cot): the bias shrinks as the light grazes instead of growing
// expect: sign
// fails: bias.decreasing_with_slope bias.growth_at_steep_slope
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  float sin_a = max(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)), 0.1);
  return u_bias_constant + u_bias_slope * u_texel_depth * min(n_dot_l / sin_a, 10.0);
}
