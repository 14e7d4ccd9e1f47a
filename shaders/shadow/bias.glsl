// The renderer's bias: a constant, or a slope-scaled bias growing with tan(angle of incidence),
// whichever is larger. Both sliders are in depth units; the slope in texels (see u_texel_depth).
uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_texel_depth;  // one shadow-map texel's world size, in depth units

// tan(angle) grows without bound at grazing light; past this the bias would lift whole shadows.
const float MAX_TAN_INCIDENCE = 10.0;

float shadow_bias(float n_dot_l) {
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
  return max(u_bias_constant, u_bias_slope * u_texel_depth * tan_incidence);
}
