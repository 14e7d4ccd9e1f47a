// wrong: the stock answer kept: width 0, a hard shadow under any sun
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch sun.penumbra_error
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return 0.0;
}
