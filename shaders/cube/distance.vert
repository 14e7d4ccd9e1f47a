#version 330 core
// Point-light shadow pass: the scene from the light's position into one cube face (six passes), or,
// with LAYERED, handed on untransformed to layers.geom, which sends every triangle to all six faces.
// ALPHA_MASK (alpha-tested casters): the material's alpha and texture coordinates go along too.
layout(location = 0) in vec3 a_position;
#ifdef ALPHA_MASK
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec2 a_uv;
#endif

#ifdef LAYERED
out vec3 g_world_position;
#ifdef ALPHA_MASK
out float g_alpha;
out vec2 g_uv;
#endif
void main() {
  g_world_position = a_position;
#ifdef ALPHA_MASK
  g_alpha = a_color.a;
  g_uv = a_uv;
#endif
}
#else
uniform mat4 u_light_view_proj;  // this face's 90-degree view
out vec3 v_world_position;
#ifdef ALPHA_MASK
out float v_alpha;
out vec2 v_uv;
#endif
void main() {
  v_world_position = a_position;
#ifdef ALPHA_MASK
  v_alpha = a_color.a;
  v_uv = a_uv;
#endif
  gl_Position = u_light_view_proj * vec4(a_position, 1.0);
}
#endif
