// wrong: faces the light, but the quad reaches size.x on each side of its axis (twice the width)
// expect: units
// fails: quad.size camera_a.*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = 2.0 * normalize(vec3(to_light.z, 0.0, -to_light.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
