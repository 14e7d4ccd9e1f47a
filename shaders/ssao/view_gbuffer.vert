#version 330 core
// SSAO's own G-buffer (renderer/ssao_pass.h): view-space position and normal per pixel.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;

uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_view_position;
out vec3 v_view_normal;

void main() {
  vec4 p = u_view * vec4(a_position, 1.0);
  v_view_position = p.xyz;
  v_view_normal = mat3(u_view) * a_normal;  // the view is rigid: its 3 x 3 part turns normals too
  gl_Position = u_projection * p;
}
