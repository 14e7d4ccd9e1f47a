#version 330 core
// Debug view for lab 4: where does the light-bleeding remap change the result? Drawn over the lit
// image (same vertices, depth test LEQUAL, blending): for each pixel it evaluates the lab's visibility
// (with the remap) and Chebyshev's bound alone (same bias, no remap), and tints the pixel by how much
// light the remap removed.
#define SHADOW_COORDS_FROM_VERTEX  // v_world_position and v_light_tex come from lit.vert
#include "shadow/common.glsl"
#include "lab/visibility.glsl"
#include "lab/bias.glsl"
#include "lab/chebyshev.glsl"

in vec3 v_normal;
in vec3 v_color;

uniform vec3 u_to_light;

layout(location = 0) out vec4 o_color;

// REMAP_TINT, and FULL_TINT_CHANGE: a change of this much visibility or more gets the full tint
// (MAX_TINT_OPACITY), smaller changes fade in from 0. Defines from the C++ side (renderer/
// debug_annotations.h kRemapTint, kRemapFullTintChange, kRemapMaxTintOpacity), which the legend reads too.

void main() {
  vec3 n = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
  float n_dot_l = dot(n, u_to_light);
  if (n_dot_l <= 0.0) discard;  // unlit by N.L anyway: no shadow test ran
  vec3 s = shadow_coords(v_world_position);
  if (outside_shadow_map(s)) discard;
  float bound = chebyshev_upper_bound(texture(u_shadow_map, s.xy).rg, s.z - shadow_bias(n_dot_l));
  float change = bound - shadow_visibility(v_world_position, n, n_dot_l);
  if (change <= 0.0) discard;
  o_color = vec4(REMAP_TINT, MAX_TINT_OPACITY * smoothstep(0.0, FULL_TINT_CHANGE, change));
}
