#version 330 core
// View-space position (w = 1 where a surface was drawn; the clear leaves 0) and unit normal, turned
// toward the camera (a two-sided surface seen from behind occludes like its front).
in vec3 v_view_position;
in vec3 v_view_normal;

layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;

void main() {
  vec3 n = normalize(v_view_normal);
  if (dot(n, v_view_position) > 0.0) n = -n;
  o_position = vec4(v_view_position, 1.0);
  o_normal = vec4(n, 0.0);
}
