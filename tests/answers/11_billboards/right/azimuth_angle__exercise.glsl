// right: the light's azimuth as an angle (atan), the quad's right axis rotated from it
// expect: variant
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  float azimuth = atan(-to_light.z, to_light.x);
  right = vec3(-sin(azimuth), 0.0, -cos(azimuth)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

bool shadow_keeps(vec2 uv, float cutoff) {
  float a = billboard_alpha(uv);
  if (a < cutoff) return false;
  return true;
}
