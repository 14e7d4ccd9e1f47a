// right: the solve by elimination with the centred moments (the Cholesky's pivots, named), the roots by the quadratic formula, the weights by branches
// expect: variant
float msm_hamburger(vec4 b, float z) {
  float variance = b.y - b.x * b.x;        // D22
  float third = b.z - b.x * b.y;            // L32 D22
  float fourth = b.w - b.y * b.y;
  float schur = fourth * variance - third * third;  // D33 D22
  float l32 = third / variance;
  // forward: y = L^-1 (1, z, z^2)
  float y2 = z - b.x;
  float y3 = z * z - b.y - l32 * y2;
  // scale by D^-1, then backward: c = L^-T y
  float c2 = y3 * variance / schur;
  float c1 = y2 / variance - l32 * c2;
  float c0 = 1.0 - b.x * c1 - b.y * c2;
  float mid = -0.5 * c1 / c2;
  float r = sqrt(max(mid * mid - c0 / c2, 0.0));
  float z1 = mid - r;
  float z2 = mid + r;
  float shadow;
  if (z2 < z) {
    // both roots in front: all but the weight at z
    shadow = 1.0 + (z1 * z2 - b.x * (z1 + z2) + b.y) / ((z2 - z) * (z - z1));
  } else if (z1 < z) {
    // only z1 in front: its weight
    shadow = (z * z2 - b.x * (z + z2) + b.y) / ((z2 - z1) * (z - z1));
  } else {
    shadow = 0.0;
  }
  return clamp(shadow, 0.0, 1.0);
}
