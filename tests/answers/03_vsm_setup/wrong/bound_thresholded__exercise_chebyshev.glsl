// wrong: rounds the bound to 0 or 1 (p > 0.5) 'to get clean shadows': the soft visibility VSM exists for is lost
// expect: compile-fine-but-wrong-formula
// fails: chebyshev.bound_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = max(moments.y - mu * mu, u_min_variance);
  if (z <= mu) return 1.0;
  float d = z - mu;
  float p = variance / (variance + d * d);
  return p > 0.5 ? 1.0 : 0.0;
}
