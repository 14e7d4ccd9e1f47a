#version 330 core
// Debug view for lab 12: each pixel tinted by the cascade it is shaded from (csm.show_cascades). Drawn
// over the lit image (same vertices, depth test LEQUAL, blending).
#include "lab/visibility.glsl"

in vec3 v_world_position;
in vec3 v_normal;
in vec3 v_color;

layout(location = 0) out vec4 o_color;

// The tints and their opacity come from the C++ side as defines (renderer/debug_annotations.h
// kCascadeTints, kCascadeTintOpacity), which the view's legend names too.
const vec3 CASCADE_TINT[8] = vec3[8](CASCADE_TINTS);

void main() { o_color = vec4(CASCADE_TINT[csm_cascade(v_world_position)], CASCADE_TINT_OPACITY); }
