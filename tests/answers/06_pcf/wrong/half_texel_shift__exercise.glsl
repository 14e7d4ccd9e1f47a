// wrong: adds half a texel to every offset ('sample texel centres'): the kernel, and so the edge, is shifted by half a texel
// expect: off-by-half-texel
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
  float bias = shadow_bias(n_dot_l) * (1.0 + float(r) + (u_pcf_hardware ? 0.5 : 0.0));
  float sum = 0.0;
  for (int y = -r; y <= r; ++y) {
    for (int x = -r; x <= r; ++x) {
      vec2 uv = s.xy + (vec2(x, y) + 0.5) * texel;
      if (u_pcf_hardware) {
        sum += texture(u_shadow_map_compare, vec3(uv, s.z - bias));
      } else {
        sum += s.z - bias > texture(u_shadow_map, uv).r ? 0.0 : 1.0;
      }
    }
  }
  return sum / float((2 * r + 1) * (2 * r + 1));
}
