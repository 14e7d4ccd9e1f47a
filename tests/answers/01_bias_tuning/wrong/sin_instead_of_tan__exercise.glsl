// wrong: uses sin(a) = sqrt(1 - n.l^2) as the slope, which stops growing at 1 where tan(a) runs away
// expect: compile-fine-but-wrong-formula
// fails: bias.growth_at_steep_slope
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  float sin_a = sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0));
  return u_bias_constant + u_bias_slope * u_texel_depth * sin_a;
}
