#version 330 core
// The view's billboards: the tree's colours, cut out with the lab's cutoff. They are not themselves
// shadowed (the lab is about the shadows they cast), and they are left out of the G-buffer's graded
// pixels (position w = 0), since the oracle's trees face the light, not the camera.
#include "billboard/shape.glsl"
in vec2 g_uv;
uniform float u_cutoff;
uniform float u_ambient;
layout(location = 0) out vec4 o_color;
layout(location = 1) out float o_visibility;
layout(location = 2) out vec4 o_position;
layout(location = 3) out vec4 o_normal;

void main() {
  float alpha = billboard_alpha(g_uv);
  if (alpha < u_cutoff) discard;
  bool trunk = abs(g_uv.x - 0.5) < 0.05 && g_uv.y < 0.4 && alpha >= 1.0;
  vec3 albedo = trunk ? vec3(0.40, 0.26, 0.13) : vec3(0.18, 0.45, 0.16) * (0.7 + 0.3 * alpha);
  vec3 linear = albedo * (u_ambient + (1.0 - u_ambient) * 0.75);
  o_color = vec4(pow(linear, vec3(1.0 / 2.2)), 1.0);
  o_visibility = 1.0;
  o_position = vec4(0.0);
  o_normal = vec4(0.0);
}
