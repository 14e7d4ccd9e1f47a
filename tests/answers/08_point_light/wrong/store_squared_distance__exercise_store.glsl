// wrong: stores the squared distance (dot(v, v), to save the sqrt) while part 2 compares distances
// expect: units
// fails: store.distance_mismatch
float value_to_store(vec3 world_position) {
  vec3 v = world_position - u_light_position;
  return dot(v, v);
}
