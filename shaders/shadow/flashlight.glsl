// The flashlight beside the sun (core/flashlight.h): a spot with a perspective shadow map of its own,
// on texture unit 5. Its test is the spot's (shadow/spot.glsl, lab 7): linear distances along its axis,
// a bias of one texel's footprint plus the slope's share. Its own uniforms, so that the sun's test keeps
// u_shadow_map and u_light_tex_matrix.
#include "shadow/slope.glsl"

uniform sampler2D u_flash_map;
uniform mat4 u_flash_tex_matrix;  // world -> the flashlight map's texture space
uniform vec3 u_flash_position;
uniform vec3 u_flash_direction;   // unit, from the flashlight toward the scene
uniform float u_flash_cos_cone;
uniform float u_flash_near, u_flash_far, u_flash_texel_angle;
uniform float u_flash_bias_slope;

// n . l toward the flashlight, 0 outside its cone.
float flashlight_n_dot_l(vec3 p, vec3 n) {
  vec3 from_light = normalize(p - u_flash_position);
  return dot(from_light, u_flash_direction) >= u_flash_cos_cone ? dot(n, -from_light) : 0.0;
}

float flashlight_linear_depth(float d) {
  float z_ndc = d * 2.0 - 1.0;
  return 2.0 * u_flash_near * u_flash_far / (u_flash_far + u_flash_near - z_ndc * (u_flash_far - u_flash_near));
}

// 1 lit, 0 shadowed by the flashlight's own map.
float flashlight_visibility(vec3 p, vec3 n, float n_dot_l) {
  vec4 h = u_flash_tex_matrix * vec4(p, 1.0);
  vec3 s = h.xyz / h.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float stored = flashlight_linear_depth(texture(u_flash_map, s.xy).r);
  float mine = flashlight_linear_depth(s.z);
  float bias = mine * u_flash_texel_angle * (1.0 + u_flash_bias_slope * shadow_tan_incidence(n_dot_l));
  return mine - bias > stored ? 0.0 : 1.0;
}
