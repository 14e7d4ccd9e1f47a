// wrong: returns (E[z^2], E[z]): the moments in the wrong channels
// expect: structure
// fails: moments.*
vec2 shadow_moments(float z) {
  float dx = dFdx(z);
  float dy = dFdy(z);
  return vec2(z * z + 0.25 * (dx * dx + dy * dy), z);
}
