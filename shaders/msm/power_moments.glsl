// The moments a moment shadow map stores (lab 14's solution): the first four powers of depth.
vec4 msm_moments(float z) {
  float z2 = z * z;
  return vec4(z, z2, z2 * z, z2 * z2);
}
