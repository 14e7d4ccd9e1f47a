// The point light's shadow test (lab 8's solution): the cube map stores, per direction from the light,
// the distance to the nearest surface. Look it up along the direction from the light to the fragment and
// compare with the fragment's own distance. 1 lit, 0 shadowed.
uniform samplerCube u_shadow_cube;
uniform float u_texel_angle;  // angle one cube-map texel spans at a face's centre (2 / size)
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)
#include "shadow/slope.glsl"

// One texel's worth of distance is always subtracted: the stored distance belongs to the texel's centre
// direction, not the fragment's.
const float CONSTANT_TEXELS = 1.0;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 from_light = world_position - u_light_position;  // the cube is addressed from the light outward
  float distance_to_light = length(from_light);
  float stored = texture(u_shadow_cube, from_light).r;
  float texel_world = distance_to_light * u_texel_angle;  // a texel's footprint at this distance
  float bias = texel_world * (CONSTANT_TEXELS + u_bias_slope * shadow_tan_incidence(n_dot_l));
  return distance_to_light - bias > stored ? 0.0 : 1.0;
}
