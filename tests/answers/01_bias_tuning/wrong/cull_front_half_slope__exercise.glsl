// wrong: culls front faces (the course's second fix for acne) and halves the slope term since culling already removes acne on lit faces; the ground is single-sided
// expect: structure
// fails: culling.shadow_error
#define SHADOW_PASS_CULL FRONT

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  float c = max(n_dot_l, 0.0995);
  float tan_a = min(sqrt(max(1.0 - c * c, 0.0)) / c, 10.0);
  return u_bias_constant + 0.5 * u_bias_slope * u_texel_depth * tan_a;
}
