// wrong: slope-scaled bias, and culls front faces 'as the other classic fix' on a scene with a single-sided ground
// expect: structure
// fails: culling.shadow_error
#define SHADOW_PASS_CULL FRONT

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

// tan(a) from cos(a) = n.l, capped near 84 degrees
float tan_incidence(float n_dot_l) {
  float c = max(n_dot_l, 1e-4);
  return min(sqrt(max(1.0 - c * c, 0.0)) / c, 10.0);
}

float shadow_bias(float n_dot_l) {
  return u_bias_constant + u_bias_slope * u_texel_depth * tan_incidence(n_dot_l);
}
