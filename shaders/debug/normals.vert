#version 330 core
// Normals debug views: positions and normals pass through in world space to normals.geom (lines) or
// flat_normals.geom (the triangles with their face normals).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
out vec3 g_position;
out vec3 g_normal;
void main() {
  g_position = a_position;
  g_normal = a_normal;
}
