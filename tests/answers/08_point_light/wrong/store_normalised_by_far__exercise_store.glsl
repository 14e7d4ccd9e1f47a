// wrong: stores the distance divided by a far distance of 25 'so it fits in [0, 1] like a depth' (the faces are R32F, and part 2 compares world units)
// expect: units
// fails: store.distance_mismatch
const float FAR = 25.0;
float value_to_store(vec3 world_position) { return length(world_position - u_light_position) / FAR; }
