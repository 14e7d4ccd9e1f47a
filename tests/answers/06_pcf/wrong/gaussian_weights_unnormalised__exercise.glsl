// wrong: weights the taps with a Gaussian (as in lab 5) but still divides by the number of taps instead of the weights' sum: lit pixels come out below 1
// expect: partial-darkening
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
  float z = s.z - shadow_bias(n_dot_l) * (1.0 + float(r) + (u_pcf_hardware ? 0.5 : 0.0));
  float sigma = max(0.5 * float(r), 0.5);
  float sum = 0.0;
  for (int y = -r; y <= r; ++y) {
    for (int x = -r; x <= r; ++x) {
      float w = exp(-float(x * x + y * y) / (2.0 * sigma * sigma));
      vec2 uv = s.xy + vec2(x, y) * texel;
      float lit = u_pcf_hardware ? texture(u_shadow_map_compare, vec3(uv, z))
                                 : (z > texture(u_shadow_map, uv).r ? 0.0 : 1.0);
      sum += w * lit;
    }
  }
  return sum / float((2 * r + 1) * (2 * r + 1));
}
