// Lab 3 exercise, part 2: how much light reaches depth z, given the (filtered) moments of the shadow
// map. Runs in the lit pass (shaders/lit.frag via labs/03_vsm_setup/visibility.glsl).
uniform float u_min_variance;  // slider "Minimum variance"

// moments = (E[z], E[z^2]) read with linear filtering; z = the fragment's depth seen from the light.
// Returns 1 for fully lit, 0 for fully shadowed.
float chebyshev_upper_bound(vec2 moments, float z) {
  // TODO: this is the plain depth test on the first moment: hard, aliased, and wrong where filtering
  // mixed depths. Use Chebyshev's inequality instead:
  //   mu = E[z], sigma^2 = E[z^2] - mu^2 (clamp it to at least u_min_variance: float cancellation);
  //   lit (1) when z <= mu, else sigma^2 / (sigma^2 + (z - mu)^2).
  return z <= moments.x ? 1.0 : 0.0;
}
