// Lab 4 exercise: fix VSM's artifacts. Edit this file; the lab reloads it when you save.
// This is lab 3's shadow test: Chebyshev's bound on the linearly filtered moments. It is included by the
// lit pass (shaders/lit.frag), with shadow_coords, outside_shadow_map and u_shadow_map from
// shaders/shadow/common.glsl.
// shadow_bias(n_dot_l): lab 1's constant + slope term (sliders "Constant bias" and "Slope bias"), and
// chebyshev_upper_bound(moments, z) (lab 3):
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

uniform float u_bleed_delta;  // slider "Light-bleeding cut (delta)", 0.125 by default

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  vec2 moments = texture(u_shadow_map, s.xy).rg;
  // TODO: on the stacked-occluder scene, light bleeds through where a high occluder's edge lies over a
  // lower one: the bound stays well above 0 on the receiver although both occluders hide it. Fix it:
  //   1. subtract the bias from the fragment's depth before the bound (shadow_bias(n_dot_l));
  //   2. remap the bound p so that [0, delta] -> 0 and [delta, 1] -> [0, 1] (delta = u_bleed_delta).
  // Tick "Show where delta acts" to see which pixels your remap changes. Then run:
  //   shadowlab check --lab 4 --impl exercise
  return chebyshev_upper_bound(moments, s.z);
}
