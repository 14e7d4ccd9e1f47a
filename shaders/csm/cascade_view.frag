#version 330 core
// Debug view for lab 12: each pixel tinted by the cascade it is shaded from (csm.show_cascades). Drawn
// over the lit image (same vertices, depth test LEQUAL, blending).
#include "lab/visibility.glsl"

in vec3 v_world_position;
in vec3 v_normal;
in vec3 v_color;

layout(location = 0) out vec4 o_color;

const vec3 CASCADE_TINT[8] = vec3[8](vec3(1.0, 0.2, 0.2), vec3(0.2, 1.0, 0.2), vec3(0.25, 0.45, 1.0), vec3(1.0, 0.9, 0.1),
                                     vec3(1.0, 0.2, 1.0), vec3(0.1, 1.0, 1.0), vec3(1.0, 0.6, 0.1), vec3(0.7, 0.7, 0.7));

void main() { o_color = vec4(CASCADE_TINT[csm_cascade(v_world_position)], 0.35); }
