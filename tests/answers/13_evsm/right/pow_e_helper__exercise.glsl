// right: e to a power through pow(), a one-sided helper called per pair, the minimum taken by hand
// expect: variant
const float E = 2.718281828459045;

vec2 evsm_warp(float z, vec2 c) {
  float positive = pow(E, c.x * z);
  float negative = -1.0 / pow(E, c.y * z);
  return vec2(positive, negative);
}

float light_through(float mean, float mean_of_square, float receiver) {
  if (receiver > mean) {
    float sigma2 = mean_of_square - mean * mean;
    if (sigma2 < 0.0) sigma2 = 0.0;
    float gap = receiver - mean;
    return sigma2 / (sigma2 + gap * gap);
  }
  return 1.0;
}

float evsm_bound(vec4 moments, vec2 w) {
  float a = light_through(moments.x, moments.y, w.x);
  float b = light_through(moments.z, moments.w, w.y);
  return a < b ? a : b;
}
