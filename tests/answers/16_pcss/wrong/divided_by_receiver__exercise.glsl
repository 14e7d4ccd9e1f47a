// wrong: the spot light's similar triangles with the receiver's distance below: (d_r - d_b) / d_r times the size
// expect: compiles, wrong formula
// fails: probe.penumbra_mismatch
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return (receiver_depth - blocker_depth) / receiver_depth * radians(light_size);
}
