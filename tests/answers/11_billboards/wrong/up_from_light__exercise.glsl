// wrong: right across the light, but up taken as size.y along to_light (the quad lies along the rays)
// expect: structure
// fails: quad.orientation camera_a.*
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = normalize(vec3(to_light.z, 0.0, -to_light.x)) * size.x;
  up = to_light * size.y;
}

bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
