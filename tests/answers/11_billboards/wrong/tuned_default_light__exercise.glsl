// wrong: the quad turned toward the lab's default light (azimuth 35 degrees), written in as a constant
// expect: tuned-to-scene
// fails: quad.orientation held_out_*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  vec3 l = vec3(cos(radians(35.0)), 0.0, -sin(radians(35.0)));
  right = normalize(vec3(l.z, 0.0, -l.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
