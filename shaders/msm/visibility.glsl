// The moment-shadow-map test (lab 14): the four-moment Hamburger bound of Peters & Klein 2015 (Moment
// Shadow Mapping, I3D; their algorithm 2), "lab/hamburger.glsl", on the linearly filtered power moments
// mixed with the moment bias, at the biased receiver depth. 1 lit, 0 shadowed, soft in between.
#include "lab/bias.glsl"
#include "lab/hamburger.glsl"

uniform float u_msm_moment_bias;  // slider "MSM moment bias" (alpha)

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec4 moments = texture(u_shadow_map, s.xy);
  // The moment bias: mixing with (0.5, 0.5, 0.5, 0.5), the moments of half the weight at depth 0 and half
  // at depth 1, keeps the Hankel matrix positive definite in float32 (the paper's 4MSM).
  vec4 b = mix(moments, vec4(0.5), u_msm_moment_bias);
  return 1.0 - msm_hamburger(b, s.z - shadow_bias(n_dot_l));
}
