#version 330 core
// The fast blur's fallback for contexts without compute shaders (vsm.blur_method = fast; the renderer
// uses shaders/vsm/fast_blur.comp where it can). The same sum as the taught shader for one direction:
//  - the weights come from the CPU, normalised there: no exp() and no division per tap;
//  - two texels per fetch: linear filtering between texels i1 = 2k - 1 and i2 = 2k at offset
//    (i1 w1 + i2 w2) / (w1 + w2) returns (w1 t1 + w2 t2) / (w1 + w2), so r + 1 fetches replace
//    2r + 1 texel reads (the centre is read alone and exactly; an odd radius's last texel alone too);
//  - the texture's CLAMP_TO_EDGE gives the taught clamp at the borders: where both texels of a pair lie
//    outside, both clamp to the edge texel, which is what the clamped reads would sum;
//  - RADIUS (and PAIRS = (RADIUS + 1) / 2) is compiled in, so the loop has a constant trip count.
// On llvmpipe a filtered fetch costs about 1.6 texel reads, so this gains ~1.5x, the compute path 2-6x.
uniform sampler2D u_moments;
uniform float u_center_weight;     // w_0
uniform vec2 u_taps[PAIRS + 1];    // (offset, weight) of the fetches on the + side; [0] unused
uniform vec2 u_inv_size;           // 1 / texture size

layout(location = 0) out vec2 o_moments;

void main() {
  vec2 uv = gl_FragCoord.xy * u_inv_size;  // this texel's centre
  vec2 step = BLUR_DIRECTION * u_inv_size;
  vec2 sum = u_center_weight * texelFetch(u_moments, ivec2(gl_FragCoord.xy), 0).rg;
  for (int k = 1; k <= PAIRS; ++k)
    sum += u_taps[k].y * (textureLod(u_moments, uv + u_taps[k].x * step, 0.0).rg +
                          textureLod(u_moments, uv - u_taps[k].x * step, 0.0).rg);
  o_moments = sum;
}
