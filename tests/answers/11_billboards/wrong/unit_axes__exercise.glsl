// wrong: faces the light, but right and up left unit length (size not applied)
// expect: units
// fails: quad.size camera_a.*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = normalize(vec3(to_light.z, 0.0, -to_light.x));
  up = vec3(0.0, 1.0, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
