// right: both parts written together, each in its own style (clamp via clamp(), step() for the lit case)
// expect: variant
uniform float u_min_variance;  // slider "Minimum variance"

float chebyshev_upper_bound(vec2 moments, float z) {
  float mean = moments.x;
  float var = clamp(moments.y - mean * mean, u_min_variance, 1.0);
  float d = z - mean;
  float bound = var / (var + d * d);
  float lit = step(z, mean);  // 1 when z <= mean
  return mix(bound, 1.0, lit);
}
