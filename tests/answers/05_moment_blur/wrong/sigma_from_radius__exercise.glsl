// wrong: computes sigma = r / 2 itself ('the kernel spans 2 sigma') and ignores the sigma slider
// expect: tuned-to-scene
// fails: held_out_*.max_texel_error
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  ivec2 last = textureSize(moments, 0) - 1;
  float sigma = 0.5 * float(u_blur_radius);
  vec2 sum = vec2(0.0);
  float total = 0.0;
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {
    float w = exp(-float(i * i) / (2.0 * sigma * sigma));
    sum += w * texelFetch(moments, clamp(texel + i * direction, ivec2(0), last), 0).rg;
    total += w;
  }
  return sum / total;
}
