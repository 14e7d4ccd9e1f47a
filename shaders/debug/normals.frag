#version 330 core
in float v_tip;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(mix(vec3(0.2, 0.9, 1.0), vec3(0.0, 0.3, 1.0), v_tip), 1.0); }
