// wrong: "more random" gradients: the sum of the texel and its swizzle, never normalised (up to twice as long)
// expect: compile-fine-but-wrong-formula
// fails: noise.range noise.matches_reference
uniform sampler2D u_noise_gradients;

vec2 grad(vec2 i) {
  vec2 size = vec2(textureSize(u_noise_gradients, 0));
  vec4 t = texture(u_noise_gradients, (i + 0.5) / size);
  return vec2(t.x, t.y) * 2.0 - 1.0 + vec2(t.y, t.x) * 2.0 - 1.0;
}

float gradient_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = p - i;
  vec2 u = f * f * (3.0 - 2.0 * f);
  float n00 = dot(grad(i), f);
  float n10 = dot(grad(i + vec2(1.0, 0.0)), f - vec2(1.0, 0.0));
  float n01 = dot(grad(i + vec2(0.0, 1.0)), f - vec2(0.0, 1.0));
  float n11 = dot(grad(i + vec2(1.0, 1.0)), f - vec2(1.0, 1.0));
  return mix(mix(n00, n10, u.x), mix(n01, n11, u.x), u.y);
}
float noise_octaves(vec2 p) { return gradient_noise(p) + 0.5 * gradient_noise(2.0 * p) + 0.25 * gradient_noise(4.0 * p); }
