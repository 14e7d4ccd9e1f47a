// wrong: tan() of the angle in degrees: the slider's 4 degrees taken as 4 radians
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) * 2.0 * tan(light_size * 0.5);
}
