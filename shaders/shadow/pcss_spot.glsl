// Percentage-closer soft shadows (Fernando, 2005) for a spot light with a size: a disk of radius
// light.size (world units) at the light's position, on the spot's perspective depth map. The steps are the
// sun's (shaders/shadow/pcss.glsl), measured in the light's own perspective:
//   1. blocker search: the stored depths in front of the point, over the directions from the light in
//      which a blocker can hide part of the disk from the point;
//   2. penumbra estimate: similar triangles between the disk, the blockers' mean distance d_b and the
//      receiver's d_r: the penumbra is 2 R (d_r - d_b) / d_b wide on the receiver;
//   3. PCF over the directions that width spans.
// Directions are measured as offsets in the plane one unit in front of the light, across the ray to the
// point ("tan units": a lateral offset x at distance d is x / d there). A blocker at distance z hides part of
// the disk if it lies within R (d_r - z) / (d_r z) of that ray: the search reaches out that far for the
// nearest possible blocker, at the map's near plane; the penumbra of radius R (d_r - d_b) / d_b on the
// receiver is R (d_r - d_b) / (d_b d_r) in tan units.
// The taps and the receiver's plane: shaders/shadow/pcss_taps.glsl. Each tap compares the stored depth
// with the receiver's plane where the tap's ray meets it, so the only bias is the spot test's own (one
// texel plus slope, shaders/shadow/spot.glsl).
// With light.size 0 it is the spot test, tap for tap. 1 lit, 0 shadowed.
#include "shadow/slope.glsl"
#include "shadow/pcss_taps.glsl"

uniform float u_light_near;   // the fitted near and far planes of the spot's projection
uniform float u_light_far;
uniform float u_texel_angle;  // world size of one texel per unit of distance: 2 tan(cone) / size
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)
uniform float u_light_size;          // light.size: the disk's radius, world units
uniform int u_pcss_blocker_samples;  // taps per side of the blocker search (their square on the spiral)
uniform int u_pcss_filter_samples;   // taps per side of the filter (their square on the spiral)

const float CONSTANT_TEXELS = 1.0;  // as the spot test: the stored depth belongs to the texel's centre

// Window depth [0, 1] back to the distance along the light's axis (inverting the perspective matrix).
float spot_linear_depth(float d) {
  float z_ndc = d * 2.0 - 1.0;
  return 2.0 * u_light_near * u_light_far / (u_light_far + u_light_near - z_ndc * (u_light_far - u_light_near));
}

// What the map holds along the ray from the light through the point `q` (world space): the stored
// distance along the light's axis, and q's own; false when q falls outside the map.
bool spot_depths(vec3 q, out float stored, out float mine) {
  vec3 s = shadow_coords(q);
  if (outside_shadow_map(s)) return false;
  stored = spot_linear_depth(texture(u_shadow_map, s.xy).r);
  mine = spot_linear_depth(s.z);
  return true;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float receiver = spot_linear_depth(s.z);
  float slope_texels = CONSTANT_TEXELS + u_bias_slope * shadow_tan_incidence(n_dot_l);
  if (u_light_size <= 0.0) {  // a point: the spot test
    float stored = spot_linear_depth(texture(u_shadow_map, s.xy).r);
    return receiver - receiver * u_texel_angle * slope_texels > stored ? 0.0 : 1.0;
  }

  // The ray to the point and two directions across it, in tan units.
  vec3 to_point = world_position - u_light_position;
  float d_r = length(to_point);
  vec3 c = to_point / d_r;
  vec3 t1 = normalize(cross(c, abs(c.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(c, t1);
  float cap = PCSS_MAX_RADIUS_TEXELS * u_texel_angle;
  float turn = interleaved_gradient_turn();
  // A distance along the axis to one along the ray, for the point's own ray (the taps' differ by less
  // than cos(cap) = 0.98 at the cap).
  float axial_to_ray = d_r / receiver;

  // 1. Blocker search: the nearest blocker possible stands at the near plane.
  float near = u_light_near * axial_to_ray;
  float search = clamp(u_light_size * (d_r - near) / (d_r * near), u_texel_angle, cap);
  int nb = u_pcss_blocker_samples * u_pcss_blocker_samples;
  float blockers = 0.0, blocker_sum = 0.0;
  for (int i = 0; i < nb; ++i) {
    vec2 o = vogel_tap(i, nb, turn) * search;
    vec3 q = ray_on_receiver_plane(normalize(c + o.x * t1 + o.y * t2), world_position, n);
    float stored, mine;
    if (!spot_depths(q, stored, mine)) continue;
    if (mine - mine * u_texel_angle * slope_texels > stored) {
      blocker_sum += stored;
      blockers += 1.0;
    }
  }
  if (blockers == 0.0) return 1.0;  // nothing in front: the whole disk is seen
  float d_b = blocker_sum / blockers * axial_to_ray;

  // 2. The penumbra's radius on the receiver, in tan units; 3. PCF over it.
  float radius = clamp(u_light_size * max(d_r - d_b, 0.0) / (d_b * d_r), 0.0, cap);
  int nf = u_pcss_filter_samples * u_pcss_filter_samples;
  float lit = 0.0, taps = 0.0;
  for (int i = 0; i < nf; ++i) {
    vec2 o = vogel_tap(i, nf, turn) * radius;
    vec3 q = ray_on_receiver_plane(normalize(c + o.x * t1 + o.y * t2), world_position, n);
    float stored, mine;
    taps += 1.0;
    if (!spot_depths(q, stored, mine)) {
      lit += 1.0;  // outside the map: nothing was drawn there to shadow it
      continue;
    }
    lit += mine - mine * u_texel_angle * slope_texels > stored ? 0.0 : 1.0;
  }
  return lit / taps;
}
