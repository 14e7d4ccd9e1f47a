// wrong: blurs the full (2r+1)^2 square in each pass (ignores direction, 2D weights): the map is blurred twice
// expect: structure
// fails: radius*.max_texel_error
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  ivec2 last = textureSize(moments, 0) - 1;
  vec2 sum = vec2(0.0);
  float total = 0.0;
  for (int y = -u_blur_radius; y <= u_blur_radius; ++y) {
    for (int x = -u_blur_radius; x <= u_blur_radius; ++x) {
      float w = exp(-float(x * x + y * y) / (2.0 * u_blur_sigma * u_blur_sigma));
      sum += w * texelFetch(moments, clamp(texel + ivec2(x, y), ivec2(0), last), 0).rg;
      total += w;
    }
  }
  return sum / total;
}
