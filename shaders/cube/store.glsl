// What a point light's shadow map stores per texel (lab 8's solution, part 1): the distance from the
// light to the nearest surface, in world units. Perspective depth (gl_FragCoord.z) would not do: it is
// not linear in distance, and each face measures it along its own axis, so the lit pass could not compare
// one number per direction.
float value_to_store(vec3 world_position) { return length(world_position - u_light_position); }
