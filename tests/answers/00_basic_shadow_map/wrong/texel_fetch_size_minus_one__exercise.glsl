// wrong: reads the texel with texelFetch at ivec2(uv * (size - 1)): the lookup drifts by up to one texel toward the map's far side
// expect: off-by-one
// fails: probe.lookup_mismatch
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  ivec2 size = textureSize(u_shadow_map, 0);
  float closest = texelFetch(u_shadow_map, ivec2(s.xy * vec2(size - 1)), 0).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
