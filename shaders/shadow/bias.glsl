// The renderer's bias, lab 1's formula: a constant plus a slope-scaled term growing with tan(angle of
// incidence), the same sum glPolygonOffset(factor, units) forms (units times the depth format's resolution
// plus factor times the depth slope). The constant is in depth units; the slope in texels (see u_texel_depth).
uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_texel_depth;  // one shadow-map texel's world size, in depth units
#include "shadow/slope.glsl"

float shadow_bias(float n_dot_l) {
  return u_bias_constant + u_bias_slope * u_texel_depth * shadow_tan_incidence(n_dot_l);
}
