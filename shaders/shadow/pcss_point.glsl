// Percentage-closer soft shadows for a point light with a size: a disk of radius light.size (world
// units) at the light's position, facing the point, on the point light's six distance faces. The same three
// steps as the spot's (shaders/shadow/pcss_spot.glsl, whose comment derives the reaches), in directions
// around the ray from the light to the point; the faces store distances along the ray, so no depth is
// converted. The face lookup and the bias are the point test's own (shaders/shadow/cube.glsl, included
// with its shadow_visibility renamed). With light.size 0 it is the point test, tap for tap.
// 1 lit, 0 shadowed.
#define shadow_visibility point_test_visibility
#include "shadow/cube.glsl"
#undef shadow_visibility
#include "shadow/pcss_taps.glsl"

uniform float u_light_near;          // the faces' fitted near plane: no blocker stands closer to the light
uniform float u_light_size;          // light.size: the disk's radius, world units
uniform int u_pcss_blocker_samples;  // taps per side of the blocker search (their square on the spiral)
uniform int u_pcss_filter_samples;   // taps per side of the filter (their square on the spiral)

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  if (u_light_size <= 0.0) return point_test_visibility(world_position, n, n_dot_l);
  vec3 to_point = world_position - u_light_position;
  float d_r = length(to_point);
  vec3 c = to_point / d_r;
  vec3 t1 = normalize(cross(c, abs(c.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(c, t1);
  float bias_texels = CONSTANT_TEXELS + u_bias_slope * cube_tan_incidence(n_dot_l);
  float cap = PCSS_MAX_RADIUS_TEXELS * u_texel_angle;
  float turn = interleaved_gradient_turn();

  // 1. Blocker search: the nearest blocker possible stands at the near plane.
  float near = max(u_light_near, 1e-4);
  float search = clamp(u_light_size * (d_r - near) / (d_r * near), u_texel_angle, cap);
  int nb = u_pcss_blocker_samples * u_pcss_blocker_samples;
  float blockers = 0.0, blocker_sum = 0.0;
  for (int i = 0; i < nb; ++i) {
    vec2 o = vogel_tap(i, nb, turn) * search;
    vec3 q = ray_on_receiver_plane(normalize(c + o.x * t1 + o.y * t2), world_position, n);
    vec3 from_light = q - u_light_position;
    float mine = length(from_light), stored = stored_distance(from_light);
    if (mine - mine * u_texel_angle * bias_texels > stored) {
      blocker_sum += stored;
      blockers += 1.0;
    }
  }
  if (blockers == 0.0) return 1.0;  // nothing in front: the whole disk is seen
  float d_b = blocker_sum / blockers;

  // 2. The penumbra's radius on the receiver, in tan units; 3. PCF over it.
  float radius = clamp(u_light_size * max(d_r - d_b, 0.0) / (d_b * d_r), 0.0, cap);
  int nf = u_pcss_filter_samples * u_pcss_filter_samples;
  float lit = 0.0;
  for (int i = 0; i < nf; ++i) {
    vec2 o = vogel_tap(i, nf, turn) * radius;
    vec3 q = ray_on_receiver_plane(normalize(c + o.x * t1 + o.y * t2), world_position, n);
    vec3 from_light = q - u_light_position;
    float mine = length(from_light);
    lit += mine - mine * u_texel_angle * bias_texels > stored_distance(from_light) ? 0.0 : 1.0;
  }
  return lit / float(nf);
}
