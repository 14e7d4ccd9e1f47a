#version 330 core
// Debug quad: what the light sees. With an orthographic light the stored depth is already linear in
// distance, so it is shown as is: near dark, far light, cleared background white.
in vec2 v_uv;
uniform sampler2D u_depth_map;
uniform vec4 u_rect;  // sub-rectangle of the map to show (x, y, w, h), for zooming in
out vec4 o_color;

void main() {
  float d = texture(u_depth_map, u_rect.xy + v_uv * u_rect.zw).r;
  o_color = vec4(vec3(d), 1.0);
}
