// Lab 10's solution: 2D gradient noise from a texture of gradients, and its octave sum.
uniform sampler2D u_noise_gradients;  // N x N texels, gradient = texel.xy * 2 - 1, repeat-wrapped
// N, the texture's size in texels, is the noise's period: textureSize(u_noise_gradients, 0).x

// The gradient stored at lattice corner i (integer coordinates; the texture repeats every N corners).
vec2 noise_gradient(vec2 i) {
  return texture(u_noise_gradients, (i + 0.5) / vec2(textureSize(u_noise_gradients, 0))).xy * 2.0 - 1.0;
}

// Perlin's quintic fade 6t^5 - 15t^4 + 10t^3: 0 and 1 at the ends with zero first and second derivatives.
vec2 noise_fade(vec2 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

float gradient_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = p - i;
  float n00 = dot(noise_gradient(i), f);
  float n10 = dot(noise_gradient(i + vec2(1.0, 0.0)), f - vec2(1.0, 0.0));
  float n01 = dot(noise_gradient(i + vec2(0.0, 1.0)), f - vec2(0.0, 1.0));
  float n11 = dot(noise_gradient(i + vec2(1.0, 1.0)), f - vec2(1.0, 1.0));
  vec2 u = noise_fade(f);
  return mix(mix(n00, n10, u.x), mix(n01, n11, u.x), u.y);
}

float noise_octaves(vec2 p) { return gradient_noise(p) + 0.5 * gradient_noise(2.0 * p) + 0.25 * gradient_noise(4.0 * p); }
