// Lab 1 exercise: the shadow bias. Edit this file; the lab reloads it when you save.
//
// Which faces the shadow pass draws into the map: NONE (both), FRONT (culls front faces, so the map
// stores back faces) or BACK. The lab reads this line when the file is saved.
#define SHADOW_PASS_CULL NONE

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

// Returns what is subtracted from the fragment's light-space depth before it is compared with the
// shadow map. n_dot_l is the cosine of the angle between the surface normal and the light (0 < n_dot_l <= 1).
float shadow_bias(float n_dot_l) {
  // TODO: a constant bias (the tutorial's first attempt) cannot be right at every angle: a surface the
  // light grazes changes depth quickly across one texel. Make the bias grow with the slope, and pick
  // the culling above. Then run: shadowlab check --lab 1 --impl exercise
  return u_bias_constant;
}
