// right: the centre tap once, then each pair +-i with one weight, clamped with min/max
// expect: variant
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  ivec2 last = textureSize(moments, 0) - ivec2(1);
  float k = 1.0 / (2.0 * u_blur_sigma * u_blur_sigma);
  vec2 sum = texelFetch(moments, texel, 0).rg;
  float total = 1.0;
  for (int i = 1; i <= u_blur_radius; ++i) {
    float w = exp(-float(i * i) * k);
    ivec2 a = max(texel - i * direction, ivec2(0));
    ivec2 b = min(texel + i * direction, last);
    sum += w * (texelFetch(moments, a, 0).rg + texelFetch(moments, b, 0).rg);
    total += 2.0 * w;
  }
  return sum / total;
}
