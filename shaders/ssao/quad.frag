#version 330 core
// A debug quad of the SSAO pass: the AO (grey, white open) or the noise vectors (x, y mapped from
// [-1, 1] to [0, 1] as red and green, shown 16 times magnified: one texel per 4 x 4 block of the quad).
in vec2 v_uv;
out vec4 o_color;

uniform sampler2D u_image;
uniform bool u_is_noise;

void main() {
  if (u_is_noise) {
    vec3 v = texture(u_image, v_uv).xyz;
    o_color = vec4(v.xy * 0.5 + 0.5, 0.5, 1.0);
  } else {
    o_color = vec4(vec3(texture(u_image, v_uv).r), 1.0);
  }
}
