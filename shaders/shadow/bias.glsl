// The renderer's bias: a constant, or a slope-scaled bias growing with tan(angle of incidence),
// whichever is larger. Both sliders are in depth units; the slope in texels (see u_texel_depth).
uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_texel_depth;  // one shadow-map texel's world size, in depth units
#include "shadow/slope.glsl"

float shadow_bias(float n_dot_l) {
  return max(u_bias_constant, u_bias_slope * u_texel_depth * shadow_tan_incidence(n_dot_l));
}
