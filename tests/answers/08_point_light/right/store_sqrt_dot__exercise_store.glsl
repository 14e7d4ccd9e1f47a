// right: stores sqrt(dot(v, v)), the length written out
// expect: variant
float value_to_store(vec3 world_position) {
  vec3 v = world_position - u_light_position;
  return sqrt(dot(v, v));
}
