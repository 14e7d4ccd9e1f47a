// wrong: mirrors the coordinates at the border (reflect) instead of clamping to the edge
// expect: structure
// fails: radius*.max_texel_error
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  ivec2 size = textureSize(moments, 0);
  vec2 sum = vec2(0.0);
  float total = 0.0;
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {
    float w = exp(-float(i * i) / (2.0 * u_blur_sigma * u_blur_sigma));
    ivec2 t = texel + i * direction;
    t = abs(t);                               // -k -> k
    t = (size - 1) - abs((size - 1) - t);     // size - 1 + k -> size - 1 - k
    sum += w * texelFetch(moments, t, 0).rg;
    total += w;
  }
  return sum / total;
}
