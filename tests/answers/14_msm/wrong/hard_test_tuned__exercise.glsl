// wrong: a hard test against the mean, offset 0.003 until the stacked slabs looked right
// expect: tuned-to-scene
// fails: hamburger.partial_mismatch
float msm_hamburger(vec4 b, float z) {
  // four moments are too noisy: compare with the mean, a little offset against acne (tuned on the slabs)
  return z > b.x + 0.003 ? 1.0 : 0.0;
}
