// The moments of EVSM (lab 13): those of the warped depth w = evsm_warp(z, c) ("lab/warp.glsl"), with
// VSM's slope term (shaders/vsm/moments.glsl) taken on w. With u_warp_exponent = 0 (vsm.warp none) the
// moments are of z: plain VSM, so one lab compares both at the same settings.
#include "lab/warp.glsl"

uniform float u_warp_exponent;  // c, already clamped for the format (renderer/moments_pass.h)
const float SLOPE_VARIANCE_FACTOR = 0.25;

vec2 shadow_moments(float z) {
  float w = u_warp_exponent > 0.0 ? evsm_warp(z, u_warp_exponent) : z;
  float dx = dFdx(w);
  float dy = dFdy(w);
  // The slope term is capped at w^2 (a standard deviation of w): at a silhouette, where dz jumps, c dz
  // can exceed 1 and w^2 times it would overflow the format (the exponent's clamp assumes at most 2 w^2).
  return vec2(w, w * w + min(SLOPE_VARIANCE_FACTOR * (dx * dx + dy * dy), w * w));
}
