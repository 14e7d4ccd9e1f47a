#version 330 core
// Depth-only: the depth test writes gl_FragCoord.z into the shadow map; no colour buffer is bound.
#ifdef ALPHA_MASK
// An alpha-tested caster cuts the same holes into the map as into the view (lit.frag's test).
in float v_alpha;
in vec2 v_uv;
uniform sampler2D u_base_color;
uniform float u_alpha_cutoff;
void main() {
  if (v_alpha * texture(u_base_color, v_uv).a < u_alpha_cutoff) discard;
}
#else
void main() {}
#endif
