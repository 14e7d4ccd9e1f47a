// A 1D Gaussian over the moments (lab 5's solution): 2r + 1 texels along `direction`, weights
// exp(-i^2 / (2 sigma^2)) divided by their sum so flat regions stay unchanged, clamped to the edge.
uniform int u_blur_radius;   // slider "Blur radius (texels)", 1..16 (radius 0 runs no pass at all)
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  // texelFetch with clamped integer coordinates: exact texel values (no filtering) and the same
  // clamp-to-edge rule as the CPU reference. textureOffset would need a constant offset (GLSL's rule).
  ivec2 last = textureSize(moments, 0) - 1;
  float two_sigma_sq = 2.0 * u_blur_sigma * u_blur_sigma;
  vec2 sum = vec2(0.0);
  float weight_sum = 0.0;
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {
    float w = exp(-float(i * i) / two_sigma_sq);
    sum += w * texelFetch(moments, clamp(texel + i * direction, ivec2(0), last), 0).rg;
    weight_sum += w;
  }
  return sum / weight_sum;
}
