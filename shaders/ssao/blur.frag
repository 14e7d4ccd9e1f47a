#version 330 core
// The AO averaged over the 4 x 4 pixels around each pixel (the noise texture's tile: the kernel's
// rotations repeat every 4 pixels, so the average of one tile holds all 16), over covered pixels only so
// that the background's 1 does not lighten the silhouettes.
in vec2 v_uv;
out float o_open;

uniform sampler2D u_open;
uniform sampler2D u_position;  // w = 1 where covered

void main() {
  vec2 texel = 1.0 / vec2(textureSize(u_open, 0));
  if (texture(u_position, v_uv).w < 0.5) {
    o_open = 1.0;
    return;
  }
  float sum = 0.0, count = 0.0;
  for (int y = -2; y < 2; ++y)
    for (int x = -2; x < 2; ++x) {
      vec2 uv = v_uv + vec2(float(x), float(y)) * texel;
      if (texture(u_position, uv).w < 0.5) continue;
      sum += texture(u_open, uv).r;
      count += 1.0;
    }
  o_open = sum / max(count, 1.0);
}
