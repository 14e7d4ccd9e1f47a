// right: right from cross(up, to_light), normalised after, whatever the light's height
// expect: variant
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  up = vec3(0.0, size.y, 0.0);
  right = size.x * normalize(cross(vec3(0.0, 1.0, 0.0), to_light));
}

bool shadow_keeps(vec2 uv, float cutoff) { return step(cutoff, billboard_alpha(uv)) > 0.5; }
