// Lab 8 exercise, part 1: what the point light's shadow pass stores. Edit this file; the lab reloads it
// when you save. It runs in the shadow pass's fragment shader (shaders/cube/distance.frag), once per
// fragment of the surface nearest the light, for each of the six 90-degree faces around the light.
// Available: u_light_position (world space); the value you return is written into an R32F texel.

// world_position: the fragment's position in world space. Returns the value its texel stores.
float value_to_store(vec3 world_position) {
  // TODO: this stores the depth buffer's value, as lab 0's map did. Part 2 must compare the fragment
  // with what is stored here, whichever of the six faces the direction falls on: is a window depth
  // (measured along each face's own axis, not linear in distance) something it can compare? Store a
  // value that means the same on every face. Then run: shadowlab check --lab 8 --impl exercise
  return gl_FragCoord.z;
}
