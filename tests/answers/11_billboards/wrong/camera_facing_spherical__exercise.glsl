// wrong: a spherical billboard facing the camera (the particle kind), with the alpha test
// expect: structure
// fails: quad.follows_camera shadow_map.follows_camera quad.orientation
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  vec3 f = normalize(eye - base);
  vec3 r = normalize(cross(vec3(0.0, 1.0, 0.0), f));
  right = r * size.x;
  up = normalize(cross(f, r)) * size.y;
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
