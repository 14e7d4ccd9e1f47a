// right: stores distance(u_light_position, world_position), the built-in
// expect: variant
float value_to_store(vec3 world_position) { return distance(u_light_position, world_position); }
