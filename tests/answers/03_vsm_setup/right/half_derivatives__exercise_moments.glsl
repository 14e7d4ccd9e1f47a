// right: halves each derivative first, (dx/2)^2 + (dy/2)^2, the same quarter
// expect: variant
vec2 shadow_moments(float z) {
  float hx = 0.5 * dFdx(z);
  float hy = 0.5 * dFdy(z);
  float second = z * z;
  second += hx * hx + hy * hy;
  return vec2(z, second);
}
