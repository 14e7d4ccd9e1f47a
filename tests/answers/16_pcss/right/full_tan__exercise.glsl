// right: tan of the full angle, with an early return for a point-sized sun
// expect: variant
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  if (light_size <= 0.0) return 0.0;
  return tan(radians(light_size)) * (receiver_depth - blocker_depth);
}
