// What every shadow test can read: the shadow map and the matrix taking world space to its texture
// space (light view-projection, then the [-1, 1] -> [0, 1] "bias matrix").
// With OWN_SHADOW_COORDS (renderer/renderer.h, Features::own_shadow_coords: lab 0, whose lesson is that
// matrix) only the map and the light's position: the lab's test maps into the map itself.
uniform sampler2D u_shadow_map;
uniform vec3 u_light_position;  // spot and point lights: where the light stands (world space)
#ifndef OWN_SHADOW_COORDS
uniform mat4 u_light_tex_matrix;

// The fragment's position in the shadow map: xy texture coordinates, z its depth seen from the light.
#ifdef SHADOW_COORDS_FROM_VERTEX
// Drawn with lit.vert, which passes the fragment's world position and that position times
// u_light_tex_matrix, both interpolated (the matrix is affine, so interpolating M p across a triangle
// gives M times the interpolated p). Since M p = M o + M (p - o) for the fragment's own position o, a
// test that asks for o (every shadow test does) gets M o with no matrix product per pixel: the compiler
// folds M (o - o) away. Any other point (an offset along the normal, say) gets the full product.
in vec3 v_world_position;
in vec4 v_light_tex;
vec3 shadow_coords(vec3 world_position) {
  vec4 p = v_light_tex + u_light_tex_matrix * vec4(world_position - v_world_position, 0.0);
  return p.xyz / p.w;
}
#else
vec3 shadow_coords(vec3 world_position) {
  vec4 p = u_light_tex_matrix * vec4(world_position, 1.0);
  return p.xyz / p.w;
}
#endif

// Outside the light's volume nothing was drawn into the map, so nothing can shadow the point.
bool outside_shadow_map(vec3 s) {
  return any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)));
}
#elif defined(SHADOW_COORDS_FROM_VERTEX)
in vec3 v_world_position;  // lit.vert's: the fragment's world position
#endif
