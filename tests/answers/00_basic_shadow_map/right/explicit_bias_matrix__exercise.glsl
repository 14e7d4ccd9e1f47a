// right: builds the course's bias matrix as a mat4 (scale 0.5, offset 0.5) and applies it to the clip-space point
// expect: variant
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

const mat4 BIAS_MATRIX = mat4(0.5, 0.0, 0.0, 0.0,
                              0.0, 0.5, 0.0, 0.0,
                              0.0, 0.0, 0.5, 0.0,
                              0.5, 0.5, 0.5, 1.0);

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 p = BIAS_MATRIX * u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = p.xyz / p.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
