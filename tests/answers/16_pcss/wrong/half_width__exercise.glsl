// wrong: the half width (tan of half the angle, not twice it): the kernel's radius returned for its width
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) * tan(radians(light_size) * 0.5);
}
