// The two warps of exponential variance shadow maps and their two-sided bound (lab 13's solution;
// Lauritzen & McCool, "Layered variance shadow maps", GI 2008).
//
// Chebyshev's bound p = sigma^2 / (sigma^2 + (z - mu)^2) bleeds where a receiver sits a little behind a
// mix of occluders: (z - mu)^2 stays small next to the mix's variance. Warping depth through a steep
// increasing function before taking moments, w = exp(c z), stretches every gap z - mu by about c w, so the
// same geometry gives a far smaller bound behind an occluder, while an unoccluded receiver (w <= mu) is
// still fully lit: the warp keeps the order of depths. exp(c z) is steep near the far plane and flat near
// the light; the negative warp -exp(-c z) is increasing too, and steep near the light. Each bound is an
// upper bound on the light, so the smaller one is the sharper.

// (w+, w-) = (exp(c+ z), -exp(-c- z)) for the exponents c = (c+, c-).
vec2 evsm_warp(float z, vec2 c) { return vec2(exp(c.x * z), -exp(-c.y * z)); }

// Chebyshev's one-sided bound on one warp's moments (E[w], E[w^2]) at the receiver's warped depth w. No
// depth-variance clamp here (lab 3's chebyshev_upper_bound has one): the negative warp's variances are
// far below any depth variance; the renderer has already floored E[w^2] in each warp's units.
float evsm_one_sided(vec2 moments, float w) {
  float mu = moments.x;
  if (w <= mu) return 1.0;
  float variance = max(moments.y - mu * mu, 0.0);
  float d = w - mu;
  return variance / (variance + d * d);
}

// The light reaching a receiver at warped depths w = evsm_warp(z, c), from the filtered moments
// (E[w+], E[w+^2], E[w-], E[w-^2]): the smaller of the two warps' bounds.
float evsm_bound(vec4 moments, vec2 w) { return min(evsm_one_sided(moments.xy, w.x), evsm_one_sided(moments.zw, w.y)); }
