// wrong: sigma^2 = mu^2 - E[z^2] (the subtraction reversed), which the clamp then hides as the minimum variance
// expect: sign
// fails: chebyshev.bound_mismatch chebyshev.min_variance_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = max(mu * mu - moments.y, u_min_variance);
  if (z <= mu) return 1.0;
  float d = z - mu;
  return variance / (variance + d * d);
}
