// right: the lab sheet's own comparison, closestDepth + 0.01 > z, with its bias 0.01 typed in instead of shadow_bias() (COURSE.md, "Artifacts and fixes")
// expect: variant
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 projCoords = clip.xyz / clip.w;
  projCoords = projCoords * 0.5 + 0.5;
  if (any(lessThan(projCoords, vec3(0.0))) || any(greaterThan(projCoords, vec3(1.0)))) return 1.0;
  float closestDepth = texture(u_shadow_map, projCoords.xy).r;
  float z = projCoords.z;
  return closestDepth + 0.01 > z ? 1.0 : 0.0;
}
