// wrong: differentiates z^2 instead of z: the slope term is (2 z)^2 times too large
// expect: compile-fine-but-wrong-formula
// fails: moments.max_second_moment_error
vec2 shadow_moments(float z) {
  float z2 = z * z;
  float dx = dFdx(z2);
  float dy = dFdy(z2);
  return vec2(z, z2 + 0.25 * (dx * dx + dy * dy));
}
