// What every shadow test can read: the shadow map and the matrix taking world space to its texture
// space (light view-projection, then the [-1, 1] -> [0, 1] "bias matrix").
uniform sampler2D u_shadow_map;
uniform mat4 u_light_tex_matrix;
uniform vec3 u_light_position;  // spot and point lights: where the light stands (world space)

// The fragment's position in the shadow map: xy texture coordinates, z its depth seen from the light.
vec3 shadow_coords(vec3 world_position) {
  vec4 p = u_light_tex_matrix * vec4(world_position, 1.0);
  return p.xyz / p.w;
}

// Outside the light's volume nothing was drawn into the map, so nothing can shadow the point.
bool outside_shadow_map(vec3 s) {
  return any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)));
}
