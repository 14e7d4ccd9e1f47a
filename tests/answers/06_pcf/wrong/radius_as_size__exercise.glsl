// wrong: treats u_pcf_radius as the kernel size N and loops -N..N: a 7x7 kernel at the 3x3 setting, 19x19 at 9x9
// expect: wrong-radius
// fails: probe.kernel_mismatch
#include "lab/bias.glsl"

uniform sampler2DShadow u_shadow_map_compare;  // the same depth texture through a comparison sampler
uniform int u_pcf_radius;    // slider "PCF kernel": N x N taps, radius (N - 1) / 2
uniform bool u_pcf_hardware; // checkbox "Hardware comparison"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  int r = u_pcf_radius;
  float bias = shadow_bias(n_dot_l) * (1.0 + float(2 * r + 1));
  float sum = 0.0;
  for (int y = -(2 * r + 1); y <= 2 * r + 1; ++y) {
    for (int x = -(2 * r + 1); x <= 2 * r + 1; ++x) {
      vec2 uv = s.xy + vec2(x, y) * texel;
      if (u_pcf_hardware) {
        sum += texture(u_shadow_map_compare, vec3(uv, s.z - bias));
      } else {
        sum += s.z - bias > texture(u_shadow_map, uv).r ? 0.0 : 1.0;
      }
    }
  }
  return sum / float((4 * r + 3) * (4 * r + 3));
}
