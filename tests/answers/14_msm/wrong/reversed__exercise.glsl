// wrong: the moments stored highest power first
// expect: structure
// fails: default.shadow_error
vec4 msm_moments(float z) {
  float z2 = z * z;
  return vec4(z2 * z2, z2 * z, z2, z);
}
