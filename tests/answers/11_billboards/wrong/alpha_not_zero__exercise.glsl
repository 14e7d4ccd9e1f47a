// wrong: cuts out only where the alpha is 0 (the usual "if (alpha == 0) discard")
// expect: compile-fine-but-wrong-formula
// fails: alpha_test.mismatch camera_a.lit_error
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = normalize(vec3(to_light.z, 0.0, -to_light.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) > 0.0; }
