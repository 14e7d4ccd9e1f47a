// Lab 14: moment shadow maps. Return the moments a texel stores for depth z in [0, 1].
//
// The renderer stores what you return in an RGBA32F texture, filters it linearly and reads it through
// the four-moment Hamburger bound (shaders/msm/visibility.glsl), which needs the first four power
// moments E[z], E[z^2], E[z^3], E[z^4]. See the lab's text.
vec4 msm_moments(float z) {
  // TODO: the third and fourth moments. With only two, the bound has nothing to work with.
  return vec4(z, z * z, 0.0, 0.0);
}
