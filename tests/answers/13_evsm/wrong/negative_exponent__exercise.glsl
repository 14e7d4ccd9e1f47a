// wrong: warps with exp(-c z), a decreasing function: the order of depths flips, so everything far reads as in front
// expect: sign
// fails: default.shadow_error
float evsm_warp(float z, float c) { return exp(-c * z); }
