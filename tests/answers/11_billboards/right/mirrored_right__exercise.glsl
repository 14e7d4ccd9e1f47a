// right: right = cross(to_light, up) the other way round (the tree is mirrored, and symmetric)
// expect: variant
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  vec3 world_up = vec3(0.0, 1.0, 0.0);
  vec3 flat_light = normalize(vec3(to_light.x, 0.0, to_light.z));
  right = cross(flat_light, world_up) * size.x;
  up = world_up * size.y;
}

bool shadow_keeps(vec2 uv, float cutoff) { return !(billboard_alpha(uv) < cutoff); }
