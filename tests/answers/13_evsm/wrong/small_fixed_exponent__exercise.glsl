// wrong: ignores the slider and uses c = 1.5, "to stay safe with half floats": too gentle to cut the bleeding
// expect: tuned-to-scene
// fails: stacked_nocut_r0.bleeding_ratio_to_vsm
float evsm_warp(float z, float c) { return exp(1.5 * z); }
