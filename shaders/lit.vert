#version 330 core
// Lit pass: the scene from the camera. Positions arrive in world space (the scene is baked).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
#ifdef MATERIAL_TEXTURE
// The material variant (scenes with a base-colour texture or an alpha mode): colour with alpha, and UVs.
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec2 a_uv;
out float v_alpha;
out vec2 v_uv;
#else
layout(location = 2) in vec3 a_color;
#endif

uniform mat4 u_view_proj;
// Neither with OWN_SHADOW_COORDS: a lab's shadow test that maps into the shadow map itself (lab 0).
#ifndef OWN_SHADOW_COORDS
uniform mat4 u_light_tex_matrix;  // world -> the shadow map's texture space (shadow/common.glsl)
#endif

out vec3 v_world_position;
out vec3 v_normal;
out vec3 v_color;
#ifndef OWN_SHADOW_COORDS
out vec4 v_light_tex;  // u_light_tex_matrix times the position, before the divide
#endif
// The shadow-volume passes draw the scene twice and test depth for equality: same inputs, same depths.
invariant gl_Position;

void main() {
  v_world_position = a_position;
  v_normal = a_normal;
#ifdef MATERIAL_TEXTURE
  v_color = a_color.rgb;
  v_alpha = a_color.a;
  v_uv = a_uv;
#else
  v_color = a_color;
#endif
#ifndef OWN_SHADOW_COORDS
  v_light_tex = u_light_tex_matrix * vec4(a_position, 1.0);
#endif
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
