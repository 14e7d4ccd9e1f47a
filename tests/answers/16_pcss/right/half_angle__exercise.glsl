// right: the exact width: two rays to the disk's rim, (d_r - d_b) 2 tan(a / 2)
// expect: variant
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  float half_angle = radians(light_size) / 2.0;
  float gap = receiver_depth - blocker_depth;
  return 2.0 * gap * tan(half_angle);
}
