// right: the warps through exp2 with the exponent times log2(e), the bound on both pairs at once in vec2
// expect: variant
const float LOG2_E = 1.4426950408889634;

vec2 evsm_warp(float z, vec2 c) {
  vec2 e = exp2(vec2(c.x, -c.y) * (z * LOG2_E));
  return vec2(e.x, -e.y);
}

float evsm_bound(vec4 moments, vec2 w) {
  vec2 mu = moments.xz;
  vec2 variance = max(moments.yw - mu * mu, vec2(0.0));
  vec2 d = w - mu;
  vec2 p = mix(variance / (variance + d * d), vec2(1.0), lessThanEqual(w, mu));  // in front of a mean: lit
  return min(p.x, p.y);
}
