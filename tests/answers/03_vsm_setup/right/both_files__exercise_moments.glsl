// right: both parts written together, each in its own style (clamp via clamp(), step() for the lit case)
// expect: variant
vec2 shadow_moments(float z) {
  float dzdx = dFdx(z), dzdy = dFdy(z);
  float m2 = z * z + (dzdx * dzdx + dzdy * dzdy) / 4.0;
  return vec2(z, m2);
}
