// wrong: clamps the variance with min(variance, u_min_variance) instead of max: the variance never exceeds the tiny minimum
// expect: compile-fine-but-wrong-formula
// fails: chebyshev.min_variance_mismatch chebyshev.bound_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = min(moments.y - mu * mu, u_min_variance);
  if (z <= mu) return 1.0;
  float d = z - mu;
  return variance / (variance + d * d);
}
