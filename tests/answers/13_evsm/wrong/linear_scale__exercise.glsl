// wrong: stretches depth by c (c z) instead of warping it: Chebyshev's bound is scale-invariant, so it is VSM again
// expect: compile-fine-but-wrong-formula
// fails: stacked_nocut_r0.bleeding_ratio_to_vsm
float evsm_warp(float z, float c) { return c * z; }
