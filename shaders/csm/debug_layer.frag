#version 330 core
// Debug quad: one cascade's depth map (a layer of the map array), as debug_depth.frag shows one map.
in vec2 v_uv;
uniform sampler2DArray u_depth_maps;
uniform float u_layer;
out vec4 o_color;

void main() { o_color = vec4(vec3(texture(u_depth_maps, vec3(v_uv, u_layer)).r), 1.0); }
