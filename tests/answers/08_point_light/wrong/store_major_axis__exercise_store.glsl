// wrong: stores the distance along the face's axis (the largest component, linear like a depth), not the Euclidean distance
// expect: units
// fails: store.distance_mismatch
float value_to_store(vec3 world_position) {
  vec3 a = abs(world_position - u_light_position);
  return max(a.x, max(a.y, a.z));
}
