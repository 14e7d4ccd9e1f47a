// wrong: declares the renderer's u_light_tex_matrix itself (the bias matrix folded in on the CPU) instead of writing the bias matrix
// expect: borrowed-helper
// fails: probe.lookup_mismatch *.shadow_error *.lit_error
#include "lab/bias.glsl"

uniform mat4 u_light_tex_matrix;  // the README: hard.glsl's matrix, bias matrix included

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 p = u_light_tex_matrix * vec4(world_position, 1.0);
  vec3 s = p.xyz / p.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
