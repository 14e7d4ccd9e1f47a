// wrong: value noise: a random value per corner (the gradient texture's red channel) blended with the fade, no dot products
// expect: structure
// fails: noise.zero_at_lattice
uniform sampler2D u_noise_gradients;

float corner_value(vec2 i) {
  vec2 size = vec2(textureSize(u_noise_gradients, 0));
  return texture(u_noise_gradients, (i + 0.5) / size).x * 2.0 - 1.0;
}

float gradient_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  float a = corner_value(i);
  float b = corner_value(i + vec2(1.0, 0.0));
  float c = corner_value(i + vec2(0.0, 1.0));
  float d = corner_value(i + vec2(1.0, 1.0));
  return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}

float noise_octaves(vec2 p) { return gradient_noise(p) + 0.5 * gradient_noise(2.0 * p) + 0.25 * gradient_noise(4.0 * p); }
