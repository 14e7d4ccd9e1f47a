#version 330 core
// Point-light shadow pass: the scene from the light's position into one cube face (six passes), or,
// with LAYERED, handed on untransformed to layers.geom, which sends every triangle to all six faces.
layout(location = 0) in vec3 a_position;

#ifdef LAYERED
out vec3 g_world_position;
void main() { g_world_position = a_position; }
#else
uniform mat4 u_light_view_proj;  // this face's 90-degree view
out vec3 v_world_position;
void main() {
  v_world_position = a_position;
  gl_Position = u_light_view_proj * vec4(a_position, 1.0);
}
#endif
