#version 330 core
// Shadow pass: the scene seen from the light. Only depth is written.
layout(location = 0) in vec3 a_position;
#ifdef ALPHA_MASK
// Alpha-tested casters (glTF MASK): the material's alpha reaches the fragment shader, which discards.
layout(location = 2) in vec4 a_color;
layout(location = 3) in vec2 a_uv;
out float v_alpha;
out vec2 v_uv;
#endif

uniform mat4 u_light_view_proj;

void main() {
#ifdef ALPHA_MASK
  v_alpha = a_color.a;
  v_uv = a_uv;
#endif
  gl_Position = u_light_view_proj * vec4(a_position, 1.0);
}
