// wrong: one exponent (c.x) for both warps
// expect: structure
// fails: warp.negative_mismatch
vec2 evsm_warp(float z, vec2 c) {
  return vec2(exp(c.x * z), -exp(-c.x * z));
}

float evsm_bound(vec4 moments, vec2 w) {
  float p[2];
  for (int i = 0; i < 2; ++i) {
    float mu = i == 0 ? moments.x : moments.z;
    float m2 = i == 0 ? moments.y : moments.w;
    float x = i == 0 ? w.x : w.y;
    float variance = max(m2 - mu * mu, 0.0);
    float d = x - mu;
    p[i] = x <= mu ? 1.0 : variance / (variance + d * d);
  }
  return min(p[0], p[1]);
}
