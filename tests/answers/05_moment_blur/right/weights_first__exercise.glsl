// right: normalises the weights before the sum (one loop for the total, one for the taps)
// expect: variant
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

float gauss(int i) { return exp(-float(i * i) / (2.0 * u_blur_sigma * u_blur_sigma)); }

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  float total = 0.0;
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) total += gauss(i);
  ivec2 size = textureSize(moments, 0);
  vec2 result = vec2(0.0);
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {
    ivec2 t = clamp(texel + direction * i, ivec2(0, 0), size - ivec2(1, 1));
    result += (gauss(i) / total) * texelFetch(moments, t, 0).rg;
  }
  return result;
}
