// wrong: the alpha test done, the shadow quad left turned toward the camera as in the view
// expect: skipped-half
// fails: quad.follows_camera shadow_map.follows_camera quad.orientation
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  vec3 to_eye = eye - base;
  right = normalize(vec3(to_eye.z, 0.0, -to_eye.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
