#version 330 core
// Billboards: one point per tree (where it stands on the ground); the geometry shader makes the quad.
layout(location = 0) in vec3 a_base;
out vec3 v_base;
void main() {
  v_base = a_base;
  gl_Position = vec4(a_base, 1.0);
}
