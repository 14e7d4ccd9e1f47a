// Cascaded shadow maps: the cascade a point is shaded from is chosen by its view depth from the camera
// the cascades were fitted to (the first whose far split lies beyond it), then one depth comparison in
// that cascade's layer of the map array. Within the blend band (csm.blend) at a cascade's far end the
// result fades into the next cascade's. 1 lit, 0 shadowed.
#include "shadow/slope.glsl"

const int CSM_MAX_CASCADES = 8;
uniform sampler2DArray u_csm_maps;
uniform mat4 u_csm_tex[CSM_MAX_CASCADES];  // world -> cascade i's texture space ([0, 1]^3)
uniform float u_csm_far[CSM_MAX_CASCADES];  // view depth where cascade i ends
uniform float u_csm_texel_depth[CSM_MAX_CASCADES];  // one texel's world size in depth units, per cascade
uniform float u_csm_near;  // where cascade 0 begins
uniform int u_csm_count;
uniform mat4 u_csm_camera_view;
uniform float u_csm_blend;
uniform float u_bias_constant;
uniform float u_bias_slope;

float csm_view_depth(vec3 world_position) { return -(u_csm_camera_view * vec4(world_position, 1.0)).z; }

// The cascade a point is shaded from; past the last split (rounding at the scene's far edge) the last.
int csm_cascade(vec3 world_position) {
  float depth = csm_view_depth(world_position);
  for (int i = 0; i < u_csm_count; ++i)
    if (depth <= u_csm_far[i]) return i;
  return u_csm_count - 1;
}

float csm_lookup(int i, vec3 world_position, float n_dot_l) {
  vec4 p = u_csm_tex[i] * vec4(world_position, 1.0);
  vec3 s = p.xyz / p.w;
  if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
  // lab 1's bias (shaders/shadow/bias.glsl), with this cascade's texel
  float bias = u_bias_constant + u_bias_slope * u_csm_texel_depth[i] * shadow_tan_incidence(n_dot_l);
  float closest = texture(u_csm_maps, vec3(s.xy, float(i))).r;
  return s.z - bias > closest ? 0.0 : 1.0;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  int i = csm_cascade(world_position);
  float visibility = csm_lookup(i, world_position, n_dot_l);
  if (u_csm_blend > 0.0 && i + 1 < u_csm_count) {
    float begin = i == 0 ? u_csm_near : u_csm_far[i - 1];
    float band_start = u_csm_far[i] - u_csm_blend * (u_csm_far[i] - begin);
    float t = (csm_view_depth(world_position) - band_start) / max(u_csm_far[i] - band_start, 1e-6);
    if (t > 0.0) visibility = mix(visibility, csm_lookup(i + 1, world_position, n_dot_l), clamp(t, 0.0, 1.0));
  }
  return visibility;
}
