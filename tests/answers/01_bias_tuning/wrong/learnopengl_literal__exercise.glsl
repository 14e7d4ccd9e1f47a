// wrong: copies the tutorial's max(0.05 * (1 - n.l), 0.005) literally: numbers for another depth range, sliders ignored
// expect: tuned-to-scene
// fails: bias.constant_slider_error bias.slope_slider_error bias.texel_size_error
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  return max(0.05 * (1.0 - n_dot_l), 0.005);
}
