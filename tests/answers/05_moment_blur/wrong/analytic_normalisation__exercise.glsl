// wrong: normalises with the continuous Gaussian's 1 / (sigma sqrt(2 pi)) instead of the sum of the discrete, truncated weights
// expect: compile-fine-but-wrong-formula
// fails: radius*.max_texel_error
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  ivec2 last = textureSize(moments, 0) - 1;
  float norm = 1.0 / (u_blur_sigma * sqrt(2.0 * 3.14159265));
  vec2 sum = vec2(0.0);
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {
    float w = norm * exp(-float(i * i) / (2.0 * u_blur_sigma * u_blur_sigma));
    sum += w * texelFetch(moments, clamp(texel + i * direction, ivec2(0), last), 0).rg;
  }
  return sum;
}
