// Percentage-closer soft shadows (Fernando, 2005) for a spot light with a size: a disk of radius
// light.size (world units) at the light's position, on the spot's perspective depth map. The sun's steps
// (shaders/shadow/pcss.glsl) measured in the light's own perspective: shaders/shadow/pcss_positional.glsl,
// shared with the point light; here, how a ray is looked up in the spot's map (distances along the light's
// axis, from the perspective depth) and the spot test's bias (one texel plus slope, shaders/shadow/spot.glsl).
// With light.size 0 it is the spot test, tap for tap. 1 lit, 0 shadowed.
#include "shadow/slope.glsl"

uniform float u_light_near;   // the fitted near and far planes of the spot's projection
uniform float u_light_far;
uniform float u_texel_angle;  // world size of one texel per unit of distance: 2 tan(cone) / size
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float CONSTANT_TEXELS = 1.0;  // as the spot test: the stored depth belongs to the texel's centre

// Window depth [0, 1] back to the distance along the light's axis (inverting the perspective matrix).
float spot_linear_depth(float d) {
  float z_ndc = d * 2.0 - 1.0;
  return 2.0 * u_light_near * u_light_far / (u_light_far + u_light_near - z_ndc * (u_light_far - u_light_near));
}

// What the map holds along the ray from the light through q, and q's own depth, along the light's axis.
bool pcss_tap(vec3 q, out float stored, out float mine) {
  vec3 s = shadow_coords(q);
  if (outside_shadow_map(s)) return false;
  stored = spot_linear_depth(texture(u_shadow_map, s.xy).r);
  mine = spot_linear_depth(s.z);
  return true;
}

#include "shadow/pcss_positional.glsl"

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float receiver = spot_linear_depth(s.z);
  float bias_texels = CONSTANT_TEXELS + u_bias_slope * shadow_tan_incidence(n_dot_l);
  if (u_light_size <= 0.0) {  // a point: the spot test
    float stored = spot_linear_depth(texture(u_shadow_map, s.xy).r);
    return receiver - receiver * u_texel_angle * bias_texels > stored ? 0.0 : 1.0;
  }
  // Along the axis to along the ray, for the point's own ray (the taps' differ by less than cos(cap) =
  // 0.98 at the cap); the near plane along the ray likewise.
  float d_r = length(world_position - u_light_position);
  float axial_to_ray = d_r / receiver;
  return pcss_positional_visibility(world_position, n, d_r, u_light_near * axial_to_ray, axial_to_ray, bias_texels,
                                    u_texel_angle);
}
