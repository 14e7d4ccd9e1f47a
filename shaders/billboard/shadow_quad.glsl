// The shadow pass's billboard (the solution of lab 11).
//
// The quad stands upright on `base` and turns about the vertical toward the LIGHT: its shadow is then
// the same from wherever the camera looks. right = the horizontal perpendicular of the light's
// direction, width long; up = world up, height long.
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  right = normalize(vec3(to_light.z, 0.0, -to_light.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

// The alpha test: the shadow map keeps the points the view keeps, those whose alpha reaches the cutoff.
bool shadow_keeps(vec2 uv, float cutoff) { return billboard_alpha(uv) >= cutoff; }
