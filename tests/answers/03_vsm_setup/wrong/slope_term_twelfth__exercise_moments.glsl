// wrong: uses the exact variance of a linear patch, 1/12 ((dz/dx)^2 + (dz/dy)^2), where the course (and the lab) asks for 1/4
// expect: compile-fine-but-wrong-formula
// fails: moments.max_second_moment_error
// A texel covers depths z + u dz/dx + v dz/dy with u, v uniform in [-1/2, 1/2]: variance (dx^2 + dy^2) / 12.
vec2 shadow_moments(float z) {
  float dx = dFdx(z);
  float dy = dFdy(z);
  return vec2(z, z * z + (dx * dx + dy * dy) / 12.0);
}
