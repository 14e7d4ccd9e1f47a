// wrong: the quad turned toward where the check's camera stands (yaw 30 degrees), so it stays put as the eye moves
// expect: tuned-to-scene
// fails: quad.orientation camera_a.*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  vec3 to_eye = vec3(sin(radians(30.0)), 0.0, cos(radians(30.0)));
  right = normalize(vec3(to_eye.z, 0.0, -to_eye.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
