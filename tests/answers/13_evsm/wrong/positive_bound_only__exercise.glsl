// wrong: the bound of the positive warp only (two-moment EVSM), the second pair ignored
// expect: skipped-half
// fails: bound.negative_mismatch
vec2 evsm_warp(float z, vec2 c) {
  return vec2(exp(c.x * z), -exp(-c.y * z));
}

float evsm_bound(vec4 moments, vec2 w) {
  // EVSM2: the positive warp is the one that sharpens the bound
  float mu = moments.x;
  if (w.x <= mu) return 1.0;
  float variance = max(moments.y - mu * mu, 0.0);
  float d = w.x - mu;
  return variance / (variance + d * d);
}
