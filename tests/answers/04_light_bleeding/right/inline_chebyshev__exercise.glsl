// right: writes Chebyshev's bound inline instead of calling chebyshev_upper_bound, and remaps only in the shadowed branch, since the lit branch's 1 maps to 1
// expect: variant
#include "lab/bias.glsl"
// lab/chebyshev.glsl for u_min_variance; the bound itself is written out below
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)", 0.125 by default

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  float z = s.z - shadow_bias(n_dot_l);
  if (z <= moments.x) return 1.0;  // in front of the mean: lit, and the remap keeps 1 at 1
  float variance = max(moments.y - moments.x * moments.x, u_min_variance);
  float d = z - moments.x;
  float p = variance / (variance + d * d);
  return clamp((p - u_bleed_delta) / (1.0 - u_bleed_delta), 0.0, 1.0);
}
