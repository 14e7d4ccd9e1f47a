#version 330 core
// Debug quads of the moments texture: the first moment, the second moment or the variance.
in vec2 v_uv;
uniform sampler2D u_moments;
uniform int u_channel;  // 0: E[z], 1: E[z^2], 2: sigma^2 = E[z^2] - E[z]^2
// EVSM (c > 0): the first two moments are of the positive warp w = exp(c z) (c = c+); shown back in depth
// units, log(E[w]) / c,
// log(E[w^2]) / 2c and the relative deviation sqrt(E[w^2] / E[w]^2 - 1) / c.
uniform float u_warp_exponent;
out vec4 o_color;

// The variance is tiny next to the moments (about a texel's depth step squared), so its square root,
// the standard deviation, is shown with a gain: sigma = 1/64 of the depth range is white.
const float STDDEV_VIEW_GAIN = 64.0;
// A negative variance (a broken moments shader) shows in red. Down to minus this much it is float
// rounding of the filtered z^2 (half an ulp of 1 is 6e-8), not an error: shown as 0.
const float ROUNDING_NOISE = 1e-7;
const vec3 NEGATIVE_COLOR = vec3(1.0, 0.1, 0.1);

void main() {
  vec2 m = texture(u_moments, v_uv).rg;
  if (u_warp_exponent > 0.0) {
    float c = u_warp_exponent;
    float shown = u_channel == 0 ? log(m.x) / c
                : u_channel == 1 ? log(m.y) / (2.0 * c)
                                 : sqrt(max(m.y / (m.x * m.x) - 1.0, 0.0)) / c * STDDEV_VIEW_GAIN;
    o_color = vec4(vec3(clamp(shown, 0.0, 1.0)), 1.0);
    return;
  }
  if (u_channel == 0) {
    o_color = vec4(vec3(m.x), 1.0);
  } else if (u_channel == 1) {
    o_color = vec4(vec3(m.y), 1.0);
  } else {
    float variance = m.y - m.x * m.x;
    o_color = variance < -ROUNDING_NOISE ? vec4(NEGATIVE_COLOR, 1.0)
                                         : vec4(vec3(clamp(sqrt(max(variance, 0.0)) * STDDEV_VIEW_GAIN, 0.0, 1.0)), 1.0);
  }
}
