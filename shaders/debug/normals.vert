#version 330 core
// Normals debug view: positions and normals pass through in world space to normals.geom.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 g_position;
out vec3 g_normal;
void main() {
  g_position = a_position;
  g_normal = a_normal;
}
