// wrong: multiplies the visibility by n.l (Lambert twice: the lit pass already does it), so lit surfaces are too dark
// expect: partial-darkening
// fails: *.lit_error
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  float lit = s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
  return lit * n_dot_l;
}
