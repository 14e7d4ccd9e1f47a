// wrong: the quad turned toward the light, but every point kept (no alpha test)
// expect: skipped-half
// fails: alpha_test.mismatch camera_a.lit_error
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = normalize(vec3(to_light.z, 0.0, -to_light.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return true; }
