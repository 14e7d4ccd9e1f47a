// wrong: the blocker's distance where the receiver's belongs: the width grows with the blocker's distance from the map's plane, not with the gap to the receiver
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return blocker_depth * 2.0 * tan(radians(light_size) * 0.5);
}
