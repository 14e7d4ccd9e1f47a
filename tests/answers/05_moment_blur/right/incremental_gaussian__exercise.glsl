// right: GPU Gems 3 ch. 40's incremental Gaussian (one exp per pass, weights by repeated multiplication), normalised by their sum
// expect: variant
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  ivec2 last = textureSize(moments, 0) - 1;
  // g.x = weight of tap i, g.y = ratio to the next, g.z = how the ratio changes: exp(-(i+1)^2/2s^2) / exp(-i^2/2s^2)
  vec3 g;
  g.x = 1.0;
  g.y = exp(-0.5 / (u_blur_sigma * u_blur_sigma));
  g.z = g.y * g.y;
  vec2 sum = g.x * texelFetch(moments, texel, 0).rg;
  float total = g.x;
  g.xy *= g.yz;
  for (int i = 1; i <= u_blur_radius; ++i) {
    sum += g.x * texelFetch(moments, clamp(texel - i * direction, ivec2(0), last), 0).rg;
    sum += g.x * texelFetch(moments, clamp(texel + i * direction, ivec2(0), last), 0).rg;
    total += 2.0 * g.x;
    g.xy *= g.yz;
  }
  return sum / total;
}
