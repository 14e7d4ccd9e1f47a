// The moments of EVSM (lab 13): those of the two warped depths (w+, w-) = evsm_warp(z, c) ("lab/warp.glsl"),
// each with VSM's slope term (shaders/vsm/moments.glsl) taken on its own warp: (E[w+], E[w+^2], E[w-],
// E[w-^2]) in an RGBA target. With u_warp_exponent = 0 (vsm.warp none) the moments are of z: plain VSM
// (the last two channels unused), so one lab compares both at the same settings.
#include "lab/warp.glsl"

#define MOMENTS_TYPE vec4
uniform float u_warp_exponent;           // c+, already clamped for the format (renderer/moments_pass.h)
uniform float u_warp_negative_exponent;  // c-, likewise
const float SLOPE_VARIANCE_FACTOR = 0.25;

// (w, w^2 + slope term). The slope term is capped at w^2 (a standard deviation of w): at a silhouette, where
// dz jumps, c dz can exceed 1 and w^2 times it would overflow the format (the exponent's clamp assumes at
// most 2 w^2).
vec2 warped_moments(float w) {
  float dx = dFdx(w);
  float dy = dFdy(w);
  return vec2(w, w * w + min(SLOPE_VARIANCE_FACTOR * (dx * dx + dy * dy), w * w));
}

vec4 shadow_moments(float z) {
  if (u_warp_exponent <= 0.0) return vec4(warped_moments(z), 0.0, 0.0);
  vec2 w = evsm_warp(z, vec2(u_warp_exponent, u_warp_negative_exponent));
  return vec4(warped_moments(w.x), warped_moments(w.y));
}
