// wrong: slope term with a magic number in depth units fitted to this scene (0.001 * tan), ignoring the texel size and the slope slider
// expect: tuned-to-scene
// fails: bias.slope_slider_error bias.texel_size_error
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

// tan(a) from cos(a) = n.l, capped near 84 degrees
float tan_incidence(float n_dot_l) {
  float c = max(n_dot_l, 1e-4);
  return min(sqrt(max(1.0 - c * c, 0.0)) / c, 10.0);
}

float shadow_bias(float n_dot_l) {
  return u_bias_constant + 0.001 * tan_incidence(n_dot_l);
}
