#version 330 core
// One-pass cube shadow map: each triangle is emitted once per face, gl_Layer choosing the face of the
// layered (cube-map) attachment. Six times the geometry-shader output for one pass over the vertices.
layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

in vec3 g_world_position[];
uniform mat4 u_face_view_proj[6];  // GL's face order: +X, -X, +Y, -Y, +Z, -Z
out vec3 v_world_position;
#ifdef ALPHA_MASK
// Alpha-tested casters: the material's alpha and texture coordinates for distance.frag's test.
in float g_alpha[];
in vec2 g_uv[];
out float v_alpha;
out vec2 v_uv;
#endif

void main() {
  for (int face = 0; face < 6; ++face) {
    for (int i = 0; i < 3; ++i) {
      gl_Layer = face;
      v_world_position = g_world_position[i];
#ifdef ALPHA_MASK
      v_alpha = g_alpha[i];
      v_uv = g_uv[i];
#endif
      gl_Position = u_face_view_proj[face] * vec4(g_world_position[i], 1.0);
      EmitVertex();
    }
    EndPrimitive();
  }
}
