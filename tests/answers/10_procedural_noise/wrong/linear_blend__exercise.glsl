// wrong: blends the four dot products linearly (u = f), no fade: creases along every texel border
// expect: compile-fine-but-wrong-formula
// fails: noise.crease
uniform sampler2D u_noise_gradients;

vec2 grad(vec2 i) {
  vec2 size = vec2(textureSize(u_noise_gradients, 0));
  return texture(u_noise_gradients, (i + 0.5) / size).xy * 2.0 - 1.0;
}

float gradient_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = p - i;
  vec2 u = f;
  float n00 = dot(grad(i), f);
  float n10 = dot(grad(i + vec2(1.0, 0.0)), f - vec2(1.0, 0.0));
  float n01 = dot(grad(i + vec2(0.0, 1.0)), f - vec2(0.0, 1.0));
  float n11 = dot(grad(i + vec2(1.0, 1.0)), f - vec2(1.0, 1.0));
  return mix(mix(n00, n10, u.x), mix(n01, n11, u.x), u.y);
}
float noise_octaves(vec2 p) { return gradient_noise(p) + 0.5 * gradient_noise(2.0 * p) + 0.25 * gradient_noise(4.0 * p); }
