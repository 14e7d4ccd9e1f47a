// wrong: the perspective (spot) formula (d_r - d_b) w / d_b with the angle as the light's width, for a sun whose rays are parallel-ish
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) * radians(light_size) / blocker_depth;
}
