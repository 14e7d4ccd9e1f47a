// wrong: both parts sloppy: no slope term in the moments and no minimum-variance clamp in the bound
// expect: skipped-half
// fails: moments.* chebyshev.*
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mu = moments.x;
  float variance = moments.y - mu * mu;
  if (z <= mu) return 1.0;
  float d = z - mu;
  return variance / (variance + d * d);
}
