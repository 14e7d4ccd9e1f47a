#version 430 core
// The fast blur's fused form for small radii (vsm.blur_method = fast, radius <= FUSED_MAX_RADIUS in
// renderer/moments_pass.cpp): both directions of the separable Gaussian in one dispatch. Each invocation
// writes a BLOCK_X x BLOCK_Y block: it reads the BLOCK_Y + 2 RADIUS rows around it (BLOCK_X + 2 RADIUS
// texels each, clamped to the edge), sums each row along X into registers, then sums those along Y.
// The same sums in the same order as the X pass then the Y pass (the intermediate stays in float32
// registers instead of an RG32F texel, which holds it exactly), but one dispatch instead of two and
// (BLOCK_X + 2r)(BLOCK_Y + 2r) / (BLOCK_X BLOCK_Y) texel reads per output. Writes into the ping-pong
// image; the renderer copies it back into the moments texture.
layout(local_size_x = LOCAL_X, local_size_y = LOCAL_Y) in;

uniform sampler2D u_moments;
layout(MOMENTS_FORMAT) uniform writeonly image2D u_out;
uniform float u_weights[RADIUS + 1];  // w_0 .. w_RADIUS

ivec2 g_size;
ivec2 g_origin;  // this invocation's first output texel

vec2 fetch(int i, int j) {  // the texel at origin + (i, j) - RADIUS, clamped to the edge
  ivec2 p = clamp(g_origin + ivec2(i, j) - ivec2(RADIUS), ivec2(0), g_size - 1);
  return texelFetch(u_moments, p, 0).rg;
}

void store(int i, int j, vec2 value) {
  ivec2 p = g_origin + ivec2(i, j);
  if (p.x < g_size.x && p.y < g_size.y) imageStore(u_out, p, vec4(value, 0.0, 0.0));
}

void main() {
  g_size = textureSize(u_moments, 0);
  g_origin = ivec2(gl_GlobalInvocationID.xy) * ivec2(BLOCK_X, BLOCK_Y);
  if (g_origin.x >= g_size.x || g_origin.y >= g_size.y) return;
  FUSED_BODY  // per row: t_k = fetch(k, row); h_row_k = the X sum; then store(k, m, the Y sum of h)
}
