// Lab 13: exponential variance shadow maps (EVSM): the two warps and the two-sided bound.
//
// z is the light-space depth in [0, 1]; c = (c+, c-) are the two exponents (sliders "EVSM exponent c+"
// and "c-", each clamped for the moments format). The renderer stores, per texel, the moments of both
// warped depths, (E[w+], E[w+^2], E[w-], E[w-^2]) with (w+, w-) = evsm_warp(z, c), blurs them like VSM's,
// raises each E[w^2] to the minimum variance in that warp's units, and calls evsm_bound with the filtered
// moments and the receiver's warped depths. See the lab's text.
//
// Write your own one-sided Chebyshev bound: lab 3's chebyshev_upper_bound is already defined (so that name
// is taken) and clamps the variance to a depth variance, far above the negative warp's variances.

// Returns (w+, w-): the positive warp of z with c.x and the negative warp with c.y. Both must be
// increasing in z.
vec2 evsm_warp(float z, vec2 c) {
  // TODO: both warps. Returning z twice is plain VSM, twice (and its light bleeding).
  return vec2(z, z);
}

// Returns the light (1 lit, 0 shadowed) that reaches a receiver at warped depths w, from the filtered
// moments (E[w+], E[w+^2], E[w-], E[w-^2]).
float evsm_bound(vec4 moments, vec2 w) {
  // TODO: the two-sided bound. This stock test is lit only in front of both means, a hard test.
  return w.x <= moments.x && w.y <= moments.z ? 1.0 : 0.0;
}
