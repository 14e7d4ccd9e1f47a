#version 330 core
// Lit pass: ambient + Lambert, with the light's term scaled by the shadow test's visibility.
// The shadow test itself comes from "lab/visibility.glsl", which a lab may point at its own file.
#include "shadow/common.glsl"
#include "lab/visibility.glsl"

in vec3 v_world_position;
in vec3 v_normal;
in vec3 v_color;

uniform vec3 u_to_light;
uniform float u_ambient;

layout(location = 0) out vec4 o_color;
#ifdef WRITE_GBUFFER
// For the oracle: visibility, world position (w = 1 marks covered pixels) and normal per pixel.
layout(location = 1) out float o_visibility;
layout(location = 2) out vec4 o_position;
layout(location = 3) out vec4 o_normal;
#endif

void main() {
  // Shade both sides of thin or open geometry: the side facing the camera is the one we see.
  vec3 n = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
  float n_dot_l = dot(n, u_to_light);
  float visibility = n_dot_l > 0.0 ? shadow_visibility(v_world_position, n, n_dot_l) : 0.0;
  vec3 linear = v_color * (u_ambient + (1.0 - u_ambient) * max(n_dot_l, 0.0) * visibility);
  o_color = vec4(pow(linear, vec3(1.0 / 2.2)), 1.0);
#ifdef WRITE_GBUFFER
  o_visibility = visibility;
  o_position = vec4(v_world_position, 1.0);
  o_normal = vec4(n, 0.0);
#endif
}
