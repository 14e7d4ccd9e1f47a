// wrong: blocker minus receiver: a negative width, so the kernel collapses to a hard shadow
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (blocker_depth - receiver_depth) * 2.0 * tan(radians(light_size) * 0.5);
}
