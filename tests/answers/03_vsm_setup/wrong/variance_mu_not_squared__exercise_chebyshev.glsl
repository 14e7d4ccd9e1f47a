// wrong: sigma^2 = E[z^2] - mu (mu not squared)
// expect: compile-fine-but-wrong-formula
// fails: chebyshev.bound_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = max(moments.y - mu, u_min_variance);
  if (z <= mu) return 1.0;
  float d = z - mu;
  return variance / (variance + d * d);
}
