// right: texelFetch with the corner wrapped by hand, smoothstep(0, 1, f) as the fade, the octaves in a loop
// expect: variant
uniform sampler2D u_noise_gradients;

vec2 gradient_at(ivec2 corner) {
  ivec2 size = textureSize(u_noise_gradients, 0);
  ivec2 wrapped = ((corner % size) + size) % size;
  return texelFetch(u_noise_gradients, wrapped, 0).rg * 2.0 - 1.0;
}

float gradient_noise(vec2 p) {
  ivec2 c = ivec2(floor(p));
  vec2 f = p - floor(p);
  vec2 s = smoothstep(0.0, 1.0, f);
  float result = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      vec2 offset = vec2(i, j);
      float w = (i == 1 ? s.x : 1.0 - s.x) * (j == 1 ? s.y : 1.0 - s.y);
      result += w * dot(gradient_at(c + ivec2(i, j)), f - offset);
    }
  return result;
}

float noise_octaves(vec2 p) {
  float sum = 0.0, amplitude = 1.0;
  for (int k = 0; k < 3; ++k) {
    sum += amplitude * gradient_noise(p);
    p *= 2.0;
    amplitude *= 0.5;
  }
  return sum;
}
