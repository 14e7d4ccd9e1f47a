#version 330 core
// Depth-only: the depth test writes gl_FragCoord.z into the shadow map; no colour buffer is bound.
void main() {}
