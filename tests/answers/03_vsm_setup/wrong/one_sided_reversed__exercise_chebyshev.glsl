// wrong: the one-sided case reversed: returns 1 when z >= mu (behind the mean) and the bound in front of it
// expect: sign
// fails: chebyshev.lit_side_mismatch
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = max(moments.y - mu * mu, u_min_variance);
  if (z >= mu) return 1.0;
  float d = z - mu;
  return variance / (variance + d * d);
}
