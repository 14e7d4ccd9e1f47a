// wrong: a constant width tuned until the lab's scene looked soft (0.12 world units at the default 4-degree sun)
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return light_size > 0.0 ? 0.12 : 0.0;
}
