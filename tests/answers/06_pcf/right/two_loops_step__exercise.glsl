// right: one loop per path (hardware or not), float loop counters, step(z, depth) for the software comparison
// expect: variant
#include "lab/bias.glsl"

uniform sampler2DShadow u_shadow_map_compare;  // the same depth texture through a comparison sampler
uniform int u_pcf_radius;    // slider "PCF kernel": N x N taps, radius (N - 1) / 2
uniform bool u_pcf_hardware; // checkbox "Hardware comparison"

// Two loops, one per path, with step() for the software comparison.
float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  ivec2 size = textureSize(u_shadow_map, 0);
  vec2 texel = vec2(1.0 / float(size.x), 1.0 / float(size.y));
  float reach = float(u_pcf_radius);
  float taps = (2.0 * reach + 1.0) * (2.0 * reach + 1.0);
  float lit = 0.0;
  if (u_pcf_hardware) {
    float z = s.z - shadow_bias(n_dot_l) * (1.5 + reach);
    for (float dy = -reach; dy <= reach; dy += 1.0)
      for (float dx = -reach; dx <= reach; dx += 1.0)
        lit += texture(u_shadow_map_compare, vec3(s.xy + vec2(dx, dy) * texel, z));
  } else {
    float z = s.z - shadow_bias(n_dot_l) * (1.0 + reach);
    for (float dy = -reach; dy <= reach; dy += 1.0)
      for (float dx = -reach; dx <= reach; dx += 1.0)
        lit += step(z, texture(u_shadow_map, s.xy + vec2(dx, dy) * texel).r);
  }
  return lit / taps;
}
