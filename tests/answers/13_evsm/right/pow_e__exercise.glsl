// right: e^(c z) written with pow
// expect: variant
float evsm_warp(float z, float c) {
  const float E = 2.718281828459045;
  return pow(E, c * z);
}
