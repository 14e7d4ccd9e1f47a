// right: scales by 1/n.l (sec a) capped at 10: at most one slope-slider's worth of texels more than tan(a), same growth at grazing light
// expect: variant
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  float sec_a = min(1.0 / max(n_dot_l, 0.1), 10.0);
  return u_bias_constant + u_bias_slope * u_texel_depth * sec_a;
}
