// Lab 0 exercise: the basic shadow test. Edit this file; the lab reloads it when you save.
// shadow_bias(n_dot_l): the slider "Constant bias" plus lab 1's slope term (0 unless "Slope bias" is set).
#include "lab/bias.glsl"

uniform mat4 u_light_view_proj;  // world -> the light's clip space, as the shadow pass used it

// Returns 1 where the light reaches the point, 0 where something nearer to the light hides it.
float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  // 1. Where the point lands in the light's clip space, divided by w (1 for an orthographic light):
  // normalised device coordinates (NDC).
  vec4 clip = u_light_view_proj * vec4(world_position, 1.0);
  vec3 s = clip.xyz / clip.w;
  // TODO: NDC run from -1 to 1 on every axis, but texture coordinates and the stored depths run
  // from 0 to 1. Apply the course's "bias matrix" (scale 0.5, offset 0.5) before using s. Then run:
  //   shadowlab check --lab 0 --impl exercise
  // 2. Outside the map nothing was drawn, so nothing can shadow the point.
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  // 3. The depth stored for that texel: the surface nearest the light.
  float closest = texture(u_shadow_map, s.xy).r;
  // 4. Farther from the light than that surface (by more than the bias): shadowed.
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
