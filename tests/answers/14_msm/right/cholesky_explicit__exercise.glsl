// right: the Hankel matrix's Cholesky factor L written out, L y = rhs then L^T c = y, and the weight at z subtracted when z is behind both roots
// expect: variant
float msm_hamburger(vec4 b, float z) {
  // B = L L^T with B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]]
  float l11 = 1.0;
  float l21 = b.x, l31 = b.y;
  float l22 = sqrt(max(b.y - l21 * l21, 1e-20));
  float l32 = (b.z - l31 * l21) / l22;
  float l33 = sqrt(max(b.w - l31 * l31 - l32 * l32, 1e-20));
  vec3 rhs = vec3(1.0, z, z * z);
  float y1 = rhs.x / l11;
  float y2 = (rhs.y - l21 * y1) / l22;
  float y3 = (rhs.z - l31 * y1 - l32 * y2) / l33;
  float c2 = y3 / l33;
  float c1 = (y2 - l32 * c2) / l22;
  float c0 = (y1 - l21 * c1 - l31 * c2) / l11;
  float half_p = 0.5 * c1 / c2;
  float r = sqrt(max(half_p * half_p - c0 / c2, 0.0));
  float z1 = -half_p - r, z2 = -half_p + r;
  if (z1 >= z) return 0.0;
  if (z2 >= z) return clamp((b.y - b.x * (z + z2) + z * z2) / ((z1 - z) * (z1 - z2)), 0.0, 1.0);
  float weight_at_z = (b.y - b.x * (z1 + z2) + z1 * z2) / ((z - z1) * (z - z2));
  return clamp(1.0 - weight_at_z, 0.0, 1.0);
}
