#version 330 core
// The shadow pass's billboards: depth only, where "lab/billboard.glsl" keeps the point (shadow_keeps).
// The colour goes nowhere in the shadow map; the debug view "shadow quads" draws the same quads in the
// camera's view with it.
#include "billboard/shape.glsl"
#include "lab/billboard.glsl"
in vec2 g_uv;
uniform float u_cutoff;
layout(location = 0) out vec4 o_color;

void main() {
  if (!shadow_keeps(g_uv, u_cutoff)) discard;
  o_color = vec4(0.95, 0.2, 0.85, 1.0);
}
