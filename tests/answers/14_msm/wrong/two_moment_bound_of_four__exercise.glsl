// wrong: Chebyshev's bound on the first two moments and on the second pair (E[z^2] as a mean), the larger shadow taken
// expect: compile-fine-but-wrong-formula
// fails: hamburger.*
float one_sided_shadow(float mean, float second, float x) {
  float variance = max(second - mean * mean, 0.0);
  float d = x - mean;
  return d <= 0.0 ? 0.0 : 1.0 - variance / (variance + d * d);
}

float msm_hamburger(vec4 b, float z) {
  // z and z^2 are both depths of a kind: bound each and keep the darker
  return max(one_sided_shadow(b.x, b.y, z), one_sided_shadow(b.y, b.w, z * z));
}
