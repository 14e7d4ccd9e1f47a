// wrong: adds dx^2 + dy^2 without the 1/4
// expect: compile-fine-but-wrong-formula
// fails: moments.max_second_moment_error
vec2 shadow_moments(float z) {
  float dx = dFdx(z);
  float dy = dFdy(z);
  return vec2(z, z * z + dx * dx + dy * dy);
}
