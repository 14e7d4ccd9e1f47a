// right: 1 / (1 + d^2 / sigma^2) with d = max(z - mu, 0), so the lit case falls out without a branch
// expect: variant
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float sigma2 = max(moments.y - mu * mu, u_min_variance);
  float d = max(z - mu, 0.0);
  return 1.0 / (1.0 + d * d / sigma2);
}
