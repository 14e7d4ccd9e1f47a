// wrong: no clamp of the coordinates: texelFetch outside the texture is undefined (zeros on Mesa) at the map's border
// expect: structure
// fails: radius*.max_texel_error
uniform int u_blur_radius;   // slider "Blur radius (texels)"
uniform float u_blur_sigma;  // slider "Blur sigma (texels)"

vec2 blur_moments(sampler2D moments, ivec2 texel, ivec2 direction) {
  vec2 sum = vec2(0.0);
  float total = 0.0;
  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {
    float w = exp(-float(i * i) / (2.0 * u_blur_sigma * u_blur_sigma));
    sum += w * texelFetch(moments, texel + i * direction, 0).rg;
    total += w;
  }
  return sum / total;
}
