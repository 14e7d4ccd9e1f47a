// right: culls back faces (the map stores the faces the light sees, as with NONE: the boxes are closed and the ground's one face is a front face), tan from sin / cos
// expect: variant
#define SHADOW_PASS_CULL BACK

uniform float u_bias_constant;  // slider "Constant bias", in depth units of the light's projection
uniform float u_bias_slope;     // slider "Slope bias", in shadow-map texels
uniform float u_texel_depth;    // one shadow-map texel's world size, in depth units

float shadow_bias(float n_dot_l) {
  float c = clamp(n_dot_l, 0.0995, 1.0);  // cos(84.3 deg): tan capped at 10
  float s = sqrt(1.0 - c * c);
  return u_bias_constant + u_bias_slope * u_texel_depth * (s / c);
}
