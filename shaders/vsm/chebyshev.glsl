// Chebyshev's one-sided inequality on the stored moments (lab 3's solution): an upper bound on the
// fraction of the texel's depths that lie at or beyond z, i.e. on how much light reaches depth z.
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  if (z <= mu) return 1.0;  // in front of the mean occluder depth: fully lit
  // E[z^2] - E[z]^2 cancels in floating point (two nearly equal numbers): the difference can come out 0
  // or even negative on a flat receiver. The clamp keeps the bound defined and smooth.
  float variance = max(moments.y - mu * mu, u_min_variance);
  float d = z - mu;
  return variance / (variance + d * d);
}
