// wrong: slope term from fwidth(z) = |dx| + |dy|, squared: (|dx| + |dy|)^2 / 4 has a cross term 2 |dx dy|
// expect: compile-fine-but-wrong-formula
// fails: moments.max_second_moment_error
vec2 shadow_moments(float z) {
  float w = fwidth(z);
  return vec2(z, z * z + 0.25 * w * w);
}
