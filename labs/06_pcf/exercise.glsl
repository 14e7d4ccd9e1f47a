// Lab 6 exercise: percentage-closer filtering. Edit this file; the lab reloads it when you save.
// shadow_bias(n_dot_l): lab 1's bias for one texel, constant + slope term.
#include "lab/bias.glsl"

uniform sampler2DShadow u_shadow_map_compare;  // the same depth texture through a comparison sampler
uniform int u_pcf_radius;    // slider "PCF kernel": N x N taps, radius (N - 1) / 2
uniform bool u_pcf_hardware; // checkbox "Hardware comparison"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  // TODO: one tap gives a hard, jagged edge: each screen pixel takes the answer of the one texel it lands
  // in. Average the comparison (not the depths!) over the (2r+1) x (2r+1) texels around s.xy, one texel
  // being 1.0 / textureSize(u_shadow_map, 0). textureOffset needs a constant offset (GLSL's rule), which
  // a loop variable is not: add the offset to the coordinate instead. With u_pcf_hardware, let texture(u_shadow_map_compare,
  // vec3(uv, depth)) do each comparison (a bilinear 2x2 PCF per tap). Mind the bias: a tap k texels away
  // reads the receiver k texels along its slope. Then run: shadowlab check --lab 6 --impl exercise
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
