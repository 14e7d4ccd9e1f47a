// wrong: z and z^2 stored twice, "the bound wants four numbers"
// expect: skipped-half
// fails: default.shadow_error
vec4 msm_moments(float z) { return vec4(z, z * z, z, z * z); }
