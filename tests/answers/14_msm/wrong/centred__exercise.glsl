// wrong: the moments of z - 0.5 ("centred for precision") where the bound expects plain powers of z
// expect: units
// fails: default.lit_error
vec4 msm_moments(float z) {
  float d = z - 0.5;
  return vec4(d, d * d, d * d * d, d * d * d * d);
}
