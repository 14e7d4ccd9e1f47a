// right: GPU Gems 3's form, max(p, z <= mu ? 1 : 0), instead of an early return
// expect: variant
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float p = (z <= moments.x) ? 1.0 : 0.0;
  float variance = moments.y - moments.x * moments.x;
  variance = max(variance, u_min_variance);
  float d = z - moments.x;
  float p_max = variance / (variance + d * d);
  return max(p, p_max);
}
