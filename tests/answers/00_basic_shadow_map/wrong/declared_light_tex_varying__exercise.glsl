// wrong: declares lit.vert's v_light_tex itself (the position already mapped into the map) instead of writing the bias matrix
// expect: borrowed-helper
// fails: probe.lookup_mismatch *.shadow_error *.lit_error
#include "lab/bias.glsl"

in vec4 v_light_tex;  // lit.vert: u_light_tex_matrix times the position

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = v_light_tex.xyz / v_light_tex.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
