// wrong: stores (z, z^2) and skips the slope term: a lit tilted receiver has zero variance
// expect: skipped-half
// fails: moments.max_second_moment_error
vec2 shadow_moments(float z) {
  return vec2(z, z * z);
}
