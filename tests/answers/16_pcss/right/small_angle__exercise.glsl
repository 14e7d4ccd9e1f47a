// right: the small-angle form: the gap times the angle in radians (what the lecture's similar triangles give)
// expect: variant
const float DEG_TO_RAD = 3.14159265 / 180.0;
float penumbra_width(float receiver_depth, float blocker_depth, float light_size) {
  return max(receiver_depth - blocker_depth, 0.0) * light_size * DEG_TO_RAD;
}
