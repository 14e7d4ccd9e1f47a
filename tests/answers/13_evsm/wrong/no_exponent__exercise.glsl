// wrong: exp(z) without the exponent: an almost linear warp on [0, 1], the bleeding stays
// expect: skipped-half
// fails: stacked_nocut_r0.bleeding_ratio_to_vsm
float evsm_warp(float z, float c) { return exp(z); }
