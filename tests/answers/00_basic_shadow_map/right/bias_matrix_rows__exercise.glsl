// right: writes the bias matrix row by row as on the course's slide and transposes it (GLSL's mat4() takes columns), applied after the divide
// expect: variant
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  // rows: x' = 0.5 x + 0.5, y' = 0.5 y + 0.5, z' = 0.5 z + 0.5
  mat4 bias_matrix = transpose(mat4(0.5, 0.0, 0.0, 0.5,
                                    0.0, 0.5, 0.0, 0.5,
                                    0.0, 0.0, 0.5, 0.5,
                                    0.0, 0.0, 0.0, 1.0));
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = (bias_matrix * vec4(clip.xyz / clip.w, 1.0)).xyz;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
