// wrong: takes tan(n.l), treating the cosine as if it were the angle
// expect: units
// fails: bias.decreasing_with_slope bias.growth_at_steep_slope
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  return u_bias_constant + u_bias_slope * u_texel_depth * tan(n_dot_l);
}
