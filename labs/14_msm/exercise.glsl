// Lab 14: moment shadow maps. Return the shadow at depth z from four (biased) moments.
//
// b = (E[z], E[z^2], E[z^3], E[z^4]) of the filter region's depths, already mixed with the moment bias
// (shaders/msm/visibility.glsl); z is the receiver's biased depth in [0, 1]. Return the sharpest lower
// bound on the share of the depth distribution strictly in front of z (1 shadowed, 0 lit) over every
// distribution with these four moments: the four-moment Hamburger bound. The renderer draws 1 minus it.
// See the lab's text for the three steps (the 3 x 3 Hankel solve, the quadratic's roots, the weights).
float msm_hamburger(vec4 b, float z) {
  // TODO: the Hamburger bound. This stock answer is Chebyshev's bound on the first two moments: VSM's
  // lower bound on the shadow, which lets light through stacked occluders.
  float variance = max(b.y - b.x * b.x, 0.0);
  float d = z - b.x;
  return d <= 0.0 ? 0.0 : 1.0 - variance / (variance + d * d);
}
