#version 330 core
// The brute-force 2D Gaussian over the moments, for comparison with the separable blurs: one pass of
// (2r + 1)^2 texel reads, weight w_i * w_j (the separable weights' outer product, normalised on the
// CPU; summed row by row, sum_j w_j sum_i w_i t_ij, which is the same sum), clamped to the edge. Same
// output as X then Y up to float rounding, with (2r + 1)^2 instead of 2 (2r + 1) reads per texel. The
// renderer copies the result (texture B) back into A.
uniform sampler2D u_moments;
uniform int u_blur_radius;
uniform float u_weights[65];  // w_|i|, i = -r..r (the renderer allows radii up to 64 here)

layout(location = 0) out vec2 o_moments;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(u_moments, 0) - 1;
  vec2 sum = vec2(0.0);
  for (int j = -u_blur_radius; j <= u_blur_radius; ++j) {
    vec2 row = vec2(0.0);
    for (int i = -u_blur_radius; i <= u_blur_radius; ++i)
      row += u_weights[abs(i)] * texelFetch(u_moments, clamp(texel + ivec2(i, j), ivec2(0), last), 0).rg;
    sum += u_weights[abs(j)] * row;
  }
  o_moments = sum;
}
