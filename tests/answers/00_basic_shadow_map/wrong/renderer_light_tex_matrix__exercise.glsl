// wrong: multiplies by the renderer's u_light_tex_matrix (in scope, the bias matrix folded in) instead of writing the bias matrix
// expect: borrowed-helper
// fails: compile_error
#include "lab/bias.glsl"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 p = u_light_tex_matrix * vec4(world_position, 1.0);  // the README: hard.glsl's matrix
  vec3 s = p.xyz / p.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
