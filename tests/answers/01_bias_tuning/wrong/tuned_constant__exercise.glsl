// wrong: keeps a constant bias and tunes it by hand until the check passes (0.007 at elevation 10)
// expect: tuned-to-scene
// fails: bias.growth_at_steep_slope bias.slope_slider_error
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  // 0.0005 gave stripes, 0.02 made the boxes float; 0.007 looks right.
  return 0.007;
}
