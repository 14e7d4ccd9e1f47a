#version 330 core
// Normals as lines (lecture 9): a triangle in, three two-vertex lines out, from each vertex p to
// p + length * n. The primitive type changes (triangles -> line strips) and so does the count.
layout(triangles) in;
layout(line_strip, max_vertices = 6) out;

in vec3 g_position[];
in vec3 g_normal[];
uniform mat4 u_view_proj;
uniform float u_normal_length;  // world units
out float v_tip;                // 0 at the surface, 1 at the tip: the line fades toward its end

void main() {
  for (int i = 0; i < 3; ++i) {
    v_tip = 0.0;
    gl_Position = u_view_proj * vec4(g_position[i], 1.0);
    EmitVertex();
    v_tip = 1.0;
    gl_Position = u_view_proj * vec4(g_position[i] + u_normal_length * normalize(g_normal[i]), 1.0);
    EmitVertex();
    EndPrimitive();
  }
}
