// wrong: applies the bias matrix to the texture coordinates only; the depth stays in clip space [-1, 1]
// expect: skipped-half
// fails: probe.* *.shadow_error
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = clip.xyz / clip.w;
  s.xy = s.xy * 0.5 + 0.5;  // the texture needs [0, 1]
  if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
