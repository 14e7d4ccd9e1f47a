// wrong: the third and fourth moments as 3z and 4z instead of z^3 and z^4
// expect: compile-fine-but-wrong-formula
// fails: default.shadow_error
vec4 msm_moments(float z) { return vec4(z, z * z, 3.0 * z, 4.0 * z); }
