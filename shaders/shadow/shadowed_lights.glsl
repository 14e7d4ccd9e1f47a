// The shadowed lights beside the sun (Features::lights, renderer/shadowed_light.h; lab 15's flashlight,
// core/flashlight.h): SHADOWED_LIGHTS of them, each a spot with a perspective shadow map of its own on the
// texture units kShadowedLightUnits names. Each one's test is the spot's (shadow/spot.glsl, lab 7): linear
// distances along its axis, a bias of one texel's footprint plus the slope's share. Their own uniforms, so
// that the sun's test keeps u_shadow_map and u_light_tex_matrix.
#include "shadow/slope.glsl"

struct ShadowedLight {
  mat4 tex_matrix;  // world -> its map's texture space
  vec3 position;
  vec3 direction;   // unit, from the light toward the scene
  float cos_cone;
  float near, far, texel_angle;
  float bias_slope;
  float intensity;  // its Lambert term's weight
};
uniform ShadowedLight u_lights[SHADOWED_LIGHTS];
// GLSL 3.30 indexes a sampler array with constant expressions only: the lit pass names each light's map
// as u_light_maps[0], u_light_maps[1], ... (shaders/lit.frag unrolls its loop).
uniform sampler2D u_light_maps[SHADOWED_LIGHTS];

// n . l toward light i, 0 outside its cone.
float shadowed_light_n_dot_l(int i, vec3 p, vec3 n) {
  vec3 from_light = normalize(p - u_lights[i].position);
  return dot(from_light, u_lights[i].direction) >= u_lights[i].cos_cone ? dot(n, -from_light) : 0.0;
}

float shadowed_light_linear_depth(int i, float d) {
  float near = u_lights[i].near, far = u_lights[i].far;
  float z_ndc = d * 2.0 - 1.0;
  return 2.0 * near * far / (far + near - z_ndc * (far - near));
}

// 1 lit, 0 shadowed by light i's own map (`map`: u_light_maps[i]).
float shadowed_light_visibility(int i, sampler2D map, vec3 p, vec3 n, float n_dot_l) {
  vec4 h = u_lights[i].tex_matrix * vec4(p, 1.0);
  vec3 s = h.xyz / h.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  float stored = shadowed_light_linear_depth(i, texture(map, s.xy).r);
  float mine = shadowed_light_linear_depth(i, s.z);
  float bias = mine * u_lights[i].texel_angle * (1.0 + u_lights[i].bias_slope * shadow_tan_incidence(n_dot_l));
  return mine - bias > stored ? 0.0 : 1.0;
}

// Light i's Lambert term times its intensity (0 outside its cone or facing away), and in `shadow` its
// shadow term (0 where it does not reach).
float shadowed_light_terms(int i, sampler2D map, vec3 p, vec3 n, out float shadow) {
  float n_dot_l = shadowed_light_n_dot_l(i, p, n);
  shadow = n_dot_l > 0.0 ? shadowed_light_visibility(i, map, p, n, n_dot_l) : 0.0;
  return u_lights[i].intensity * max(n_dot_l, 0.0);
}
