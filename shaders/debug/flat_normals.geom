#version 330 core
// Flat normals (lecture 9): a triangle in, the same triangle out, each of its three vertices carrying
// the triangle's face normal instead of its own (smooth) vertex normal. The face normal is the cross
// product of two edges taken in the triangle's own order (counter-clockwise seen from the front), so
// it points out of the front face; positions are in world space, and so is the normal.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 g_position[];
in vec3 g_normal[];  // the vertices' own normals: not used, the face decides
uniform mat4 u_view_proj;
out vec3 v_face_normal;  // world space, unit length, the same at the three vertices

void main() {
  vec3 a = g_position[0], b = g_position[1], c = g_position[2];
  vec3 n = normalize(cross(b - a, c - a));
  for (int i = 0; i < 3; ++i) {
    v_face_normal = n;
    gl_Position = u_view_proj * vec4(g_position[i], 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
