// wrong: the store half of only_store_done (part 1 right)
// expect: skipped-half
float value_to_store(vec3 world_position) { return length(world_position - u_light_position); }
