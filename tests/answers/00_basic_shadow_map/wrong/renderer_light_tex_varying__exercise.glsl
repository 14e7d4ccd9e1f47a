// wrong: reads lit.vert's interpolated v_light_tex (the position already mapped into the map) in the lit pass, the matrix elsewhere
// expect: borrowed-helper
// fails: compile_error
#include "lab/bias.glsl"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
#ifdef SHADOW_COORDS_FROM_VERTEX
  vec3 s = v_light_tex.xyz / v_light_tex.w;  // lit.vert did the work
#else
  vec4 p = u_light_tex_matrix * vec4(world_position, 1.0);
  vec3 s = p.xyz / p.w;
#endif
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
