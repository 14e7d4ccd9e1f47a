// right: the negative warp as -(1 / exp(c z)), the variance as E[(w - mu)^2] written out, min() kept
// expect: variant
vec2 evsm_warp(float z, vec2 c) {
  return vec2(exp(z * c.x), -(1.0 / exp(z * c.y)));
}

float chebyshev_one_sided(float mu, float second, float x) {
  float d = x - mu;
  if (d <= 0.0) return 1.0;
  float variance = max(second - mu * mu, 0.0);
  return 1.0 / (1.0 + d * d / variance);
}

float evsm_bound(vec4 moments, vec2 w) {
  return min(chebyshev_one_sided(moments.x, moments.y, w.x), chebyshev_one_sided(moments.z, moments.w, w.y));
}
