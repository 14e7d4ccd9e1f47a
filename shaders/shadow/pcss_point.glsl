// Percentage-closer soft shadows for a point light with a size: a disk of radius light.size (world
// units) at the light's position, facing the point, on the point light's six distance faces. The steps are
// the spot's (shaders/shadow/pcss_positional.glsl); the faces store distances along the rays, so nothing is
// converted. The face lookup and the bias are the point test's own (shaders/shadow/cube.glsl, included with
// its shadow_visibility renamed). With light.size 0 it is the point test, tap for tap. 1 lit, 0 shadowed.
#define shadow_visibility point_test_visibility
#include "shadow/cube.glsl"
#undef shadow_visibility

uniform float u_light_near;  // the faces' fitted near plane: nothing stands closer to the light

// What the faces hold along the ray from the light through q, and q's own distance.
bool pcss_tap(vec3 q, out float stored, out float mine) {
  vec3 from_light = q - u_light_position;
  stored = stored_distance(from_light);
  mine = length(from_light);
  return true;
}

#include "shadow/pcss_positional.glsl"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  if (u_light_size <= 0.0) return point_test_visibility(world_position, n, n_dot_l);
  float bias_texels = CONSTANT_TEXELS + u_bias_slope * cube_tan_incidence(n_dot_l);
  return pcss_positional_visibility(world_position, n, length(world_position - u_light_position),
                                    max(u_light_near, 1e-4), 1.0, bias_texels, u_texel_angle);
}
