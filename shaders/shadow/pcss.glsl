// Percentage-closer soft shadows (Fernando, 2005) for a directional light with a size (the sun's disk,
// light.size its angular diameter in degrees), on the plain ortho shadow map:
//   1. blocker search: the stored depths in front of the point, over the part of the map from which the
//      light's disk can be hidden, averaged: the blockers' mean distance;
//   2. penumbra estimate: penumbra_width() from "lab/penumbra.glsl" (lab 16's exercise), from the
//      receiver's and the blockers' distances and the light's size;
//   3. PCF over a kernel as wide as that penumbra (each tap a hardware 2 x 2 comparison).
// Each tap compares against the receiver's own plane at the tap (the plane through the point with normal
// n, in the map's coordinates), so a wide kernel needs no bias growing with its reach. With light.size 0
// it is the hard test (shaders/shadow/hard.glsl), tap for tap. 1 lit, 0 shadowed.
#include "lab/bias.glsl"
#include "lab/penumbra.glsl"

uniform sampler2DShadow u_shadow_map_compare;  // the same depth texture, through a comparison sampler
uniform float u_light_size;          // light.size: the sun's angular diameter, degrees
uniform int u_pcss_blocker_samples;  // taps per side of the blocker search
uniform int u_pcss_filter_samples;   // taps per side of the filter

// The kernel's half width is capped at this many texels (a wide kernel of a few taps only shows steps).
const float PCSS_MAX_RADIUS_TEXELS = 64.0;

// The debug view (pcss.view: 0 the shading, 1 the blockers' mean distance, 2 the filter's width): what
// shadow_visibility found for this pixel, shown by technique_view() in place of the lit colour.
#define TECHNIQUE_VIEW
uniform int u_pcss_view;
// The value shown yellow (renderer/debug_annotations.h pcss_view_range, which the legend reads too): the
// blockers' distance (world units), or the kernel's width (texels: twice PCSS_MAX_RADIUS_TEXELS).
uniform float u_pcss_view_range;
float pcss_seen_distance = -1.0;  // the blockers' mean distance above the point; -1: no blocker found
float pcss_seen_width = 0.0;      // the filter's diameter, map texels (the wider axis)
bool pcss_seen_capped = false;    // the cap (PCSS_MAX_RADIUS_TEXELS) cut the kernel

// Row i of u_light_tex_matrix (world -> map texture space): its length is 1 / (the ortho box's world
// extent along that axis).
vec3 pcss_row(int i) { return vec3(u_light_tex_matrix[0][i], u_light_tex_matrix[1][i], u_light_tex_matrix[2][i]); }

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float bias = shadow_bias(n_dot_l);
  if (u_light_size <= 0.0) {  // a point: the hard test (its blocker's distance kept for the view)
    float stored = texture(u_shadow_map, s.xy).r;
    if (s.z - bias <= stored) return 1.0;
    pcss_seen_distance = (s.z - stored) / length(pcss_row(2));
    return 0.0;
  }

  vec3 rx = pcss_row(0), ry = pcss_row(1), rz = pcss_row(2);
  vec2 world_per_uv = vec2(1.0 / length(rx), 1.0 / length(ry));
  float world_per_depth = 1.0 / length(rz);
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  // The receiver's plane: the map depth at s.xy + d is s.z + dot(grad, d). With the normal in the map's
  // axes (unit rows), a step du, dv across the plane moves -(n.x du W + n.y dv H) / n.z in depth.
  vec3 nl = vec3(dot(n, rx) * world_per_uv.x, dot(n, ry) * world_per_uv.y, dot(n, rz) * world_per_depth);
  float nz = min(nl.z, -0.1);  // facing the light: depth grows away from it; grazing planes clamped
  vec2 grad = -vec2(nl.x * world_per_uv.x, nl.y * world_per_uv.y) / (nz * world_per_depth);

  // 1. Blocker search over the region within which a blocker can hide part of the disk: a blocker at the
  // map's near plane (distance 0) hides it from receiver_depth x tan(half the angular size) away.
  float receiver_depth = s.z * world_per_depth;
  float reach = receiver_depth * tan(radians(u_light_size) * 0.5);
  vec2 search = clamp(reach / world_per_uv, texel, texel * PCSS_MAX_RADIUS_TEXELS);
  float blockers = 0.0, blocker_sum = 0.0;
  float b = float(u_pcss_blocker_samples);
  for (int y = 0; y < u_pcss_blocker_samples; ++y) {
    for (int x = 0; x < u_pcss_blocker_samples; ++x) {
      vec2 d = ((vec2(x, y) + 0.5) / b * 2.0 - 1.0) * search;
      float stored = texture(u_shadow_map, s.xy + d).r;
      if (stored < s.z + dot(grad, d) - bias) {
        blocker_sum += stored;
        blockers += 1.0;
      }
    }
  }
  if (blockers == 0.0) return 1.0;  // nothing in front: the whole disk is seen
  float blocker_depth = blocker_sum / blockers * world_per_depth;
  pcss_seen_distance = receiver_depth - blocker_depth;

  // 2. The penumbra's width on the receiver (world units), as a kernel radius in texture units.
  float width = penumbra_width(receiver_depth, blocker_depth, u_light_size);
  vec2 wanted = 0.5 * width / world_per_uv;
  vec2 radius = clamp(wanted, vec2(0.0), texel * PCSS_MAX_RADIUS_TEXELS);
  pcss_seen_width = 2.0 * max(radius.x / texel.x, radius.y / texel.y);
  pcss_seen_capped = any(greaterThan(wanted, texel * PCSS_MAX_RADIUS_TEXELS));

  // 3. PCF over a disk of that diameter, the sun's own shape: behind a blocker parallel to the receiver
  // the share of the disk's taps that are lit is the share of the sun the point sees. (A square kernel
  // would ramp over up to sqrt(2) times the width across a diagonal edge.)
  float f = float(u_pcss_filter_samples);
  float lit = 0.0, taps = 0.0;
  for (int y = 0; y < u_pcss_filter_samples; ++y) {
    for (int x = 0; x < u_pcss_filter_samples; ++x) {
      vec2 g = (vec2(x, y) + 0.5) / f * 2.0 - 1.0;
      if (dot(g, g) > 1.0) continue;
      vec2 d = g * radius;
      lit += texture(u_shadow_map_compare, vec3(s.xy + d, s.z + dot(grad, d) - bias));
      taps += 1.0;
    }
  }
  return lit / taps;
}

// The debug view's colour for this pixel, after shadow_visibility ran (lit: whether it did, the surface
// facing the light). False with pcss.view 0. A value t in [0, 1] is (t, t^2, 0.6 (1 - t)): dark blue to
// yellow, t itself in the red channel (tests/test_gl_soft_check.cpp reads it back).
bool technique_view(bool lit, out vec3 color) {
  color = vec3(0.0);
  if (u_pcss_view == 0) return false;
  if (!lit) {
    color = vec3(0.15);
  } else if (pcss_seen_distance < 0.0) {
    color = vec3(0.7);
  } else if (u_pcss_view == 2 && pcss_seen_capped) {
    color = vec3(1.0, 0.0, 0.0);
  } else {
    // The width on a log scale, 0 to the cap: 1, 4, 16 and 64 texels at 0.14, 0.33, 0.58 and 0.86.
    float t = u_pcss_view == 1 ? pcss_seen_distance / u_pcss_view_range
                               : log2(1.0 + pcss_seen_width) / log2(1.0 + u_pcss_view_range);
    t = clamp(t, 0.0, 1.0);
    color = vec3(t, t * t, 0.6 * (1.0 - t));
  }
  return true;
}
