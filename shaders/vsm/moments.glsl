// The moments a texel stores (lab 3's solution): E[z] and E[z^2] of the depths it covers.
//
// One texel covers a small patch of a tilted surface, so its depths are not one value but a spread.
// Treating z as linear across the pixel, z(x + u, y + v) = z + u dz/dx + v dz/dy with u, v uniform in
// [-1/2, 1/2], its variance is (1/12)((dz/dx)^2 + (dz/dy)^2); the course rounds 1/12 up to 1/4, which
// also covers the derivative's coarse per-quad estimate. Without this term a tilted receiver has
// sigma^2 = 0 and Chebyshev's bound drops to 0 just behind mu: acne.
const float SLOPE_VARIANCE_FACTOR = 0.25;

vec2 shadow_moments(float z) {
  float dx = dFdx(z);
  float dy = dFdy(z);
  return vec2(z, z * z + SLOPE_VARIANCE_FACTOR * (dx * dx + dy * dy));
}
