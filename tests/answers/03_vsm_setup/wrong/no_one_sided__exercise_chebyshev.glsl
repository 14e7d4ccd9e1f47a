// wrong: always returns sigma^2 / (sigma^2 + (z - mu)^2), without the lit case z <= mu: lit surfaces slightly darkened
// expect: partial-darkening
// fails: chebyshev.lit_side_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = max(moments.y - mu * mu, u_min_variance);
  float d = z - mu;
  return variance / (variance + d * d);
}
