// Percentage-closer filtering (lab 6's solution): average the depth comparison, not the depths, over
// N x N neighbouring texels (3 x 3 in the lecture). With u_pcf_hardware every tap goes through a
// sampler2DShadow (GL_COMPARE_REF_TO_TEXTURE with linear filtering): the texture unit compares the four
// nearest texels and blends the results bilinearly, a 2 x 2 PCF per tap at no extra cost.
#include "lab/bias.glsl"

uniform sampler2DShadow u_shadow_map_compare;  // the same depth texture, through a comparison sampler
uniform int u_pcf_radius;    // (N - 1) / 2
uniform bool u_pcf_hardware;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  // A tap k texels away reads the receiver k texels along its slope: the bias must reach that far too.
  // The corner taps are r sqrt(2) texels away; half a texel more for a hardware tap's bilinear footprint.
  float reach = 1.0 + 1.41421356 * float(u_pcf_radius) + (u_pcf_hardware ? 0.5 : 0.0);
  float z = s.z - shadow_bias(n_dot_l) * reach;
  float lit = 0.0;
  // Loop offsets are not constant, so texture() with a computed coordinate, not textureOffset (GLSL
  // requires its offset to be a constant expression).
  for (int y = -u_pcf_radius; y <= u_pcf_radius; ++y) {
    for (int x = -u_pcf_radius; x <= u_pcf_radius; ++x) {
      vec2 uv = s.xy + vec2(x, y) * texel;
      if (u_pcf_hardware)
        lit += texture(u_shadow_map_compare, vec3(uv, z));
      else
        lit += z > texture(u_shadow_map, uv).r ? 0.0 : 1.0;
    }
  }
  float taps = float((2 * u_pcf_radius + 1) * (2 * u_pcf_radius + 1));
  return lit / taps;
}
