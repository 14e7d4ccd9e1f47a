// wrong: keeps the stock's window depth (gl_FragCoord.z), as lab 0's map stored, and does only part 2
// expect: skipped-half
// fails: store.distance_mismatch
float value_to_store(vec3 world_position) { return gl_FragCoord.z; }
