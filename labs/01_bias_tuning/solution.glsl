// Lab 1 solution: a slope-scaled bias; both faces in the shadow map (culling front faces leaks on this scene: INSTRUCTOR.md).
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_texel_depth;

// Past this the bias would lift whole shadows off their casters (tan 84 deg is about 10).
const float MAX_TAN_INCIDENCE = 10.0;

float shadow_bias(float n_dot_l) {
  // Across one texel, a surface tilted by angle a from the light changes depth by texel * tan(a): that is
  // the error a single stored depth makes. Bias by a few texels' worth of it, plus a small constant for
  // the depth format's rounding.
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
  return u_bias_constant + u_bias_slope * u_texel_depth * tan_incidence;
}
