// Lab 1 solution: a slope-scaled bias; both faces in the shadow map (see the README for culling).
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_texel_depth;
// tan_incidence(n_dot_l): tan(a) from n . l, capped near 84 degrees, past which the bias would lift
// whole shadows off their casters.
#include "shadow/slope.glsl"

float shadow_bias(float n_dot_l) {
  // Across one texel, a surface tilted by angle a from the light changes depth by texel * tan(a): that is
  // the error a single stored depth makes. Bias by a few texels' worth of it, plus a small constant for
  // the depth format's rounding.
  return u_bias_constant + u_bias_slope * u_texel_depth * tan_incidence(n_dot_l);
}
