// Alpha-tested casters (glTF MASK) in the shadow passes. The renderer draws them through the ALPHA_MASK
// variant of a pass's program, where alpha_test() discards what the view discards (lit.frag's test: the
// base colour's alpha, factor x vertex colour x texture, below the material's cutoff), so the map gets
// the holes the view and the oracle have. In the pass's own program it does nothing.
#ifdef ALPHA_MASK
in float v_alpha;
in vec2 v_uv;
uniform sampler2D u_base_color;
uniform float u_alpha_cutoff;
void alpha_test() {
  if (v_alpha * texture(u_base_color, v_uv).a < u_alpha_cutoff) discard;
}
#else
void alpha_test() {}
#endif
