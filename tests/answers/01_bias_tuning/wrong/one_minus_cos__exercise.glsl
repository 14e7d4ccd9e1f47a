// wrong: grows the bias with (1 - n.l) instead of tan(a): bounded by one texel's worth, far too small at grazing light
// expect: compile-fine-but-wrong-formula
// fails: bias.growth_at_steep_slope
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  return u_bias_constant + u_bias_slope * u_texel_depth * (1.0 - n_dot_l);
}
