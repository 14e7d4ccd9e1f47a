// wrong: uses the standard deviation sigma where the bound needs sigma^2: sigma / (sigma + (z - mu)^2)
// expect: units
// fails: chebyshev.bound_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float sigma = sqrt(max(moments.y - mu * mu, u_min_variance));
  if (z <= mu) return 1.0;
  float d = z - mu;
  return sigma / (sigma + d * d);
}
