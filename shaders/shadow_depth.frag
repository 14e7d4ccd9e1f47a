#version 330 core
// Depth-only: the depth test writes gl_FragCoord.z into the shadow map; no colour buffer is bound. An
// alpha-tested caster (the ALPHA_MASK variant) cuts the same holes into the map as into the view.
#include "shadow/alpha_mask.glsl"

void main() { alpha_test(); }
