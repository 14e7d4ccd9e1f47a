// wrong: the bound sharpened with a smoothstep tuned on the stacked slabs
// expect: tuned-to-scene
// fails: hamburger.partial_mismatch
float msm_hamburger(vec4 b, float z) {
  // Cholesky factorisation (LDL^T) of the Hankel matrix B = [[1, b1, b2], [b1, b2, b3], [b2, b3, b4]],
  // only its non-trivial entries.
  float L32D22 = -b.x * b.y + b.z;
  float D22 = -b.x * b.x + b.y;
  float squared_depth_variance = -b.y * b.y + b.w;
  float D33D22 = squared_depth_variance * D22 - L32D22 * L32D22;
  float inv_D22 = 1.0 / D22;
  float L32 = L32D22 * inv_D22;
  // Solve B c = (1, z, z^2): forward substitution, scaling, backward substitution.
  vec3 c = vec3(1.0, z, z * z);
  c.y -= b.x;
  c.z -= b.y + L32 * c.y;
  c.y *= inv_D22;
  c.z *= D22 / D33D22;
  c.y -= L32 * c.z;
  c.x -= dot(c.yz, b.xy);
  // The two other support points: the roots of c.x + c.y x + c.z x^2.
  float p = c.y / c.z;
  float q = c.x / c.z;
  float r = sqrt(max(p * p * 0.25 - q, 0.0));
  float z1 = -p * 0.5 - r;
  float z2 = -p * 0.5 + r;
  // The weight of the support points strictly in front of z: both roots (1 minus z2's weight), z1's
  // alone, or none.
  vec4 s = z2 < z ? vec4(z1, z, 1.0, 1.0) : (z1 < z ? vec4(z, z1, 0.0, 1.0) : vec4(0.0));
  float quotient = (s.x * z2 - b.x * (s.x + z2) + b.y) / ((z2 - s.y) * (z - z1));
  return smoothstep(0.2, 0.8, clamp(s.z + s.w * quotient, 0.0, 1.0));  // crisper edges
}
