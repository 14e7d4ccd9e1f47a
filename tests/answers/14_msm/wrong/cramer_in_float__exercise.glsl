// wrong: the 3 x 3 system by Cramer's rule in float32 (right in exact arithmetic): determinants of the nearly singular Hankel matrix cancel
// expect: float-precision
// fails: hamburger.partial_mismatch hamburger.behind_mismatch
float det3(vec3 a, vec3 b, vec3 c) { return dot(a, cross(b, c)); }

float msm_hamburger(vec4 b, float z) {
  vec3 col0 = vec3(1.0, b.x, b.y), col1 = vec3(b.x, b.y, b.z), col2 = vec3(b.y, b.z, b.w);
  vec3 rhs = vec3(1.0, z, z * z);
  float d = det3(col0, col1, col2);
  float c0 = det3(rhs, col1, col2) / d;
  float c1 = det3(col0, rhs, col2) / d;
  float c2 = det3(col0, col1, rhs) / d;
  float p = c1 / c2, q = c0 / c2;
  float r = sqrt(max(0.25 * p * p - q, 0.0));
  float z1 = -0.5 * p - r, z2 = -0.5 * p + r;
  // weights of z1 and z2 in the three-point distribution {z, z1, z2} with moments 1, b.x, b.y
  float w1 = (b.y - b.x * (z + z2) + z * z2) / ((z1 - z) * (z1 - z2));
  float w2 = (b.y - b.x * (z + z1) + z * z1) / ((z2 - z) * (z2 - z1));
  float shadow = 0.0;
  if (z1 < z) shadow += w1;
  if (z2 < z) shadow += w2;
  return clamp(shadow, 0.0, 1.0);
}
