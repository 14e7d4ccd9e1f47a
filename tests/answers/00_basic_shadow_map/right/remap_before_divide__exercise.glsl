// right: remaps in homogeneous form before the divide, (xyz + w) / 2, which is also right for a perspective light
// expect: variant
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = 0.5 * (clip.xyz + vec3(clip.w)) / clip.w;
  bool outside = any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)));
  if (outside) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  float receiver = s.z - shadow_bias(n_dot_l);
  return step(receiver, closest);
}
