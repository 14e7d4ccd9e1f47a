// wrong: both parts sloppy: no slope term in the moments and no minimum-variance clamp in the bound
// expect: skipped-half
// fails: moments.* chebyshev.*
vec2 shadow_moments(float z) {
  return vec2(z, z * z);
}
