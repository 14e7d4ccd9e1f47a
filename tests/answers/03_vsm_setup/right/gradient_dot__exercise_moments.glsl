// right: slope term as 0.25 * dot(g, g) with g = vec2(dFdx(z), dFdy(z))
// expect: variant
vec2 shadow_moments(float z) {
  vec2 g = vec2(dFdx(z), dFdy(z));
  return vec2(z, z * z + 0.25 * dot(g, g));
}
