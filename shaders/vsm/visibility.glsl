// The renderer's variance-shadow-map test (lab 4's solution): Chebyshev's bound on the linearly
// filtered (and, with a blur radius, Gaussian-blurred) moments, with a depth bias and the
// light-bleeding remap. 1 lit, 0 shadowed, soft in between.
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)"

// Where two occluders overlap in the filter region, the bound stays well above 0 on the receiver
// below them (light bleeding), but only up to some fraction. Cutting [0, delta] to 0 and stretching
// [delta, 1] back to [0, 1] removes those values; true penumbrae get a little darker and narrower.
float reduce_light_bleeding(float p, float delta) {
  return clamp((p - delta) / (1.0 - delta), 0.0, 1.0);
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;  // linear filtering: the 2x2 texels' moments averaged
  float p = chebyshev_upper_bound(moments, s.z - shadow_bias(n_dot_l));
  return reduce_light_bleeding(p, u_bleed_delta);
}
