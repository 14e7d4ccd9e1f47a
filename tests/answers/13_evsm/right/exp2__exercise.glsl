// right: exp through exp2 and log2(e)
// expect: variant
float evsm_warp(float z, float c) { return exp2(c * z * 1.4426950408889634); }
