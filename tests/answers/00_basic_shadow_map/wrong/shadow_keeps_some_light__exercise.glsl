// wrong: returns 0.3 in shadow 'so shadows are not pitch black' (the lit pass already adds the ambient term)
// expect: partial-darkening
// fails: *.shadow_error probe.lookup_mismatch
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.3 : 1.0;
}
