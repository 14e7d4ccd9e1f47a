#version 430 core
// The fast separable Gaussian over the moments (vsm.blur_method = fast): the same sum as the taught
// shader (shaders/vsm/gaussian_blur.glsl) for one direction, computed so that llvmpipe does less work:
//  - the weights w_|i| come from the CPU (normalised there), so no exp() and no division per tap;
//  - each invocation writes OUTPUTS consecutive texels along the blur direction and reads the
//    OUTPUTS + 2 RADIUS texels they share once, into registers: 1 + 2 RADIUS / OUTPUTS texel reads per
//    output instead of 2 RADIUS + 1 (texel reads are what llvmpipe pays for, multiply-adds are cheap);
//  - RADIUS and OUTPUTS are compiled in and the code is unrolled by the renderer
//    (FAST_BLUR_FETCHES, FAST_BLUR_SUMS: see MomentsPass), so every index is a constant.
// Reads with texelFetch at clamped coordinates (the taught clamp-to-edge rule), writes with imageStore.
layout(local_size_x = LOCAL_X, local_size_y = LOCAL_Y) in;

uniform sampler2D u_moments;
layout(MOMENTS_FORMAT) uniform writeonly image2D u_out;
uniform float u_weights[RADIUS + 1];  // w_0 .. w_RADIUS

const ivec2 DIRECTION = BLUR_DIRECTION;  // (1, 0): X pass, (0, 1): Y pass
const ivec2 ACROSS = ivec2(1) - DIRECTION;

int g_n;       // texels along the direction
int g_start;   // this invocation's first output along the direction
int g_line;    // its row (X pass) or column (Y pass)

vec2 fetch(int j) {  // the texel at along = g_start - RADIUS + j, clamped to the edge
  int along = clamp(g_start - RADIUS + j, 0, g_n - 1);
  return texelFetch(u_moments, DIRECTION * along + ACROSS * g_line, 0).rg;
}

void store(int k, vec2 value) {
  if (g_start + k < g_n) imageStore(u_out, DIRECTION * (g_start + k) + ACROSS * g_line, vec4(value, 0.0, 0.0));
}

void main() {
  ivec2 size = textureSize(u_moments, 0);
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  g_n = DIRECTION.x == 1 ? size.x : size.y;
  g_start = (DIRECTION.x == 1 ? id.x : id.y) * OUTPUTS;
  g_line = DIRECTION.x == 1 ? id.y : id.x;
  if (g_line >= (DIRECTION.x == 1 ? size.y : size.x) || g_start >= g_n) return;
  vec2 t[OUTPUTS + 2 * RADIUS];
  FAST_BLUR_FETCHES  // t[j] = fetch(j), j = 0 .. OUTPUTS + 2 RADIUS - 1
  FAST_BLUR_SUMS     // store(k, w_0 t[k + RADIUS] + sum_i w_i (t[k + RADIUS + i] + t[k + RADIUS - i])), k < OUTPUTS
}
