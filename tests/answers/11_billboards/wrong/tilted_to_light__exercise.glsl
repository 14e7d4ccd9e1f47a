// wrong: the quad faces the light squarely (a spherical billboard toward the light): the tree leans
// expect: structure
// fails: quad.orientation camera_a.*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  vec3 r = normalize(cross(vec3(0.0, 1.0, 0.0), to_light));
  right = r * size.x;
  up = normalize(cross(to_light, r)) * size.y;
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
