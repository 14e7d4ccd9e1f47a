// PCSS for a positional light with a size (a disk of radius light.size, world units, at the light's
// position): the steps of the spot's and the point light's tests (shaders/shadow/pcss_spot.glsl,
// pcss_point.glsl), which differ only in how a direction is looked up in their maps. Before including this
// file, a test defines
//   bool pcss_tap(vec3 q, out float stored, out float mine)
// the distance its map holds along the ray from the light through the point q (world space) and q's own,
// in one measure (false: q falls outside the map, where nothing was drawn to shadow it).
//
//   1. blocker search: the stored distances in front of the point, over the directions from the light in
//      which a blocker can hide part of the disk from the point;
//   2. penumbra estimate: similar triangles between the disk, the blockers' mean distance d_b and the
//      receiver's d_r: the penumbra is 2 R (d_r - d_b) / d_b wide on the receiver;
//   3. PCF over the directions that width spans.
// Directions are offsets in the plane one unit in front of the light, across the ray to the point ("tan
// units": a lateral offset x at distance d is x / d there). A blocker at distance z hides part of the disk
// if it lies within R (d_r - z) / (d_r z) of that ray: the search reaches that far for the nearest
// blocker possible, at the map's near plane; the penumbra's radius R (d_r - d_b) / d_b on the receiver is
// R (d_r - d_b) / (d_b d_r) in tan units.
// The taps lie on a Vogel spiral (a golden-angle disk: no rows, so a wide region shows no staircase),
// turned per pixel by an interleaved-gradient angle (Jimenez 2014), so that neighbouring pixels sample
// between each other's taps. Each tap compares the map with the receiver's plane where the tap's ray meets
// it (the plane through the point with normal n), so a wide kernel needs no bias growing with its reach:
// only the light's hard test's own (bias_texels texels of its footprint).
uniform float u_light_size;          // light.size: the disk's radius, world units
uniform int u_pcss_blocker_samples;  // taps per side of the blocker search (their square on the spiral)
uniform int u_pcss_filter_samples;   // taps per side of the filter (their square on the spiral)

// The search and the kernel reach at most this many texels from the point's own (a wide kernel of a few
// taps only shows noise; measured on lab 8's light: a cap of 256 raised the penumbra error, 0.098 ->
// 0.101 at radius 0.8 and 0.048 -> 0.085 at 0.2, tests/test_gl_pcss_lights.cpp).
const float PCSS_MAX_RADIUS_TEXELS = 64.0;
const float GOLDEN_ANGLE = 2.39996323;

// Tap i of n on a Vogel spiral in the unit disk, turned by `turn` radians.
vec2 vogel_tap(int i, int n, float turn) {
  float r = sqrt((float(i) + 0.5) / float(n));
  float a = float(i) * GOLDEN_ANGLE + turn;
  return r * vec2(cos(a), sin(a));
}

// Per-pixel angle from the pixel's position (Jimenez, "Next generation post processing in Call of Duty:
// Advanced Warfare", 2014): fixed for a pixel, so a still frame is still.
float interleaved_gradient_turn() {
  return 6.28318531 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

// The point where the ray from the light with direction `dir` meets the receiver's plane (through p, normal
// n); p itself where the plane is seen edge-on or lies behind the light along that ray.
vec3 ray_on_receiver_plane(vec3 dir, vec3 p, vec3 n) {
  float facing = dot(dir, n);
  if (abs(facing) < 1e-4) return p;
  float t = dot(p - u_light_position, n) / facing;
  return t > 0.0 ? u_light_position + t * dir : p;
}

// One tap around the ray to the point: whether the map holds something in front of the receiver's plane
// there (the hard test's comparison with its bias), and what it holds.
struct PcssTap {
  bool inside, blocked;
  float stored;
};

// Tap `o` (tan units) around the ray c (unit) with the directions t1, t2 across it.
PcssTap pcss_tap_at(vec2 o, vec3 c, vec3 t1, vec3 t2, vec3 p, vec3 n, float bias_texels, float texel_angle) {
  PcssTap t;
  float mine;
  t.inside = pcss_tap(ray_on_receiver_plane(normalize(c + o.x * t1 + o.y * t2), p, n), t.stored, mine);
  t.blocked = t.inside && mine - mine * texel_angle * bias_texels > t.stored;
  return t;
}

// The visible share of the disk at p (normal n), d_r from the light. `near`: the least distance along the
// ray at which the map holds anything; `to_ray`: the map's measure of distance to one along the ray to p
// (1 where the map stores distances along the rays); `texel_angle`: a texel's footprint per unit of
// distance. With light.size 0 the caller runs its hard test instead.
float pcss_positional_visibility(vec3 p, vec3 n, float d_r, float near, float to_ray, float bias_texels,
                                 float texel_angle) {
  vec3 c = (p - u_light_position) / d_r;
  vec3 t1 = normalize(cross(c, abs(c.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(c, t1);
  float cap = PCSS_MAX_RADIUS_TEXELS * texel_angle;
  float turn = interleaved_gradient_turn();

  // 1. Blocker search: the nearest blocker possible stands at the near plane.
  float search = clamp(u_light_size * (d_r - near) / (d_r * near), texel_angle, cap);
  int nb = u_pcss_blocker_samples * u_pcss_blocker_samples;
  float blockers = 0.0, blocker_sum = 0.0;
  for (int i = 0; i < nb; ++i) {
    PcssTap t = pcss_tap_at(vogel_tap(i, nb, turn) * search, c, t1, t2, p, n, bias_texels, texel_angle);
    if (t.blocked) {
      blocker_sum += t.stored;
      blockers += 1.0;
    }
  }
  if (blockers == 0.0) return 1.0;  // nothing in front: the whole disk is seen
  float d_b = blocker_sum / blockers * to_ray;

  // 2. The penumbra's radius on the receiver, in tan units; 3. PCF over it (a tap outside the map is lit).
  float radius = clamp(u_light_size * max(d_r - d_b, 0.0) / (d_b * d_r), 0.0, cap);
  int nf = u_pcss_filter_samples * u_pcss_filter_samples;
  float lit = 0.0;
  for (int i = 0; i < nf; ++i)
    lit += pcss_tap_at(vogel_tap(i, nf, turn) * radius, c, t1, t2, p, n, bias_texels, texel_angle).blocked ? 0.0 : 1.0;
  return lit / float(nf);
}
