// right: the powers with pow()
// expect: variant
vec4 msm_moments(float z) { return vec4(z, pow(z, 2.0), pow(z, 3.0), pow(z, 4.0)); }
