// wrong: the receiver's distance alone: as if every blocker stood at the map's near plane (the blocker search's reach, not the penumbra)
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return receiver_depth * 2.0 * tan(radians(light_size) * 0.5);
}
