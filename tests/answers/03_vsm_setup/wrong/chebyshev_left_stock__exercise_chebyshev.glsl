// wrong: writes the moments (the solution's) but leaves part 2 as the stock hard test on the first moment
// expect: skipped-half
// fails: chebyshev.*
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  return z <= moments.x ? 1.0 : 0.0;
}
