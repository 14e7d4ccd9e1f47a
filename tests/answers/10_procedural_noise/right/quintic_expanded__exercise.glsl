// right: Perlin's quintic fade written out as a polynomial, the bilinear blend expanded, the sum as 0.25 (4n(p) + 2n(2p) + n(4p))
// expect: variant
uniform sampler2D u_noise_gradients;

float corner_dot(vec2 corner, vec2 p) {
  vec2 g = 2.0 * texture(u_noise_gradients, (corner + vec2(0.5)) / float(textureSize(u_noise_gradients, 0).x)).xy - vec2(1.0);
  return dot(g, p - corner);
}

float gradient_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 t = p - i;
  vec2 u = 10.0 * t * t * t - 15.0 * t * t * t * t + 6.0 * t * t * t * t * t;
  float a = corner_dot(i, p);
  float b = corner_dot(i + vec2(1.0, 0.0), p);
  float c = corner_dot(i + vec2(0.0, 1.0), p);
  float d = corner_dot(i + vec2(1.0, 1.0), p);
  return a + (b - a) * u.x + (c - a) * u.y + (a - b - c + d) * u.x * u.y;
}

float noise_octaves(vec2 p) { return 0.25 * (4.0 * gradient_noise(p) + 2.0 * gradient_noise(2.0 * p) + gradient_noise(4.0 * p)); }
