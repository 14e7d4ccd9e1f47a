// wrong: the blocker-receiver distance alone: the width ignores the light's size (a 10-degree sun and a 1-degree one give the same penumbra)
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return receiver_depth - blocker_depth;
}
