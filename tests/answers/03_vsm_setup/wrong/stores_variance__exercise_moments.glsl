// wrong: stores the variance (the slope term alone) in green instead of the second moment E[z^2]
// expect: structure
// fails: moments.*
vec2 shadow_moments(float z) {
  float dx = dFdx(z);
  float dy = dFdy(z);
  return vec2(z, 0.25 * (dx * dx + dy * dy));
}
