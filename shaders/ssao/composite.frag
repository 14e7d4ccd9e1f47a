#version 330 core
// The lit picture times the AO (blended ZERO, SRC_COLOR onto it): the open share darkens creases and
// contacts. A simplification for display: a renderer would scale only the ambient (indirect) term.
in vec2 v_uv;
out vec4 o_factor;

uniform sampler2D u_open;

void main() {
  o_factor = vec4(vec3(texture(u_open, v_uv).r), 1.0);
}
