// wrong: sigma^2 = E[z^2] - mu^2 without the minimum-variance clamp
// expect: compile-fine-but-wrong-formula
// fails: chebyshev.min_variance_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = moments.y - mu * mu;
  if (z <= mu) return 1.0;
  float d = z - mu;
  return variance / (variance + d * d);
}
