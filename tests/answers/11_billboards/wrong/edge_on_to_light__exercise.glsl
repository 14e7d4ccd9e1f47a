// wrong: right along the light's horizontal direction instead of across it (the quad seen edge-on)
// expect: structure
// fails: quad.orientation camera_a.*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = normalize(vec3(to_light.x, 0.0, to_light.z)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
