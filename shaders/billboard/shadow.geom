#version 330 core
// The shadow pass's billboards: each point becomes the quad "lab/billboard.glsl" builds (shadow_quad),
// seen from the light.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
#include "billboard/shape.glsl"
#include "lab/billboard.glsl"
in vec3 v_base[];
out vec2 g_uv;
uniform mat4 u_light_view_proj;
uniform vec3 u_to_light;  // unit, toward the light
uniform vec3 u_eye;       // the camera's position
uniform vec2 u_size;      // width, height

void main() {
  vec3 base = v_base[0];
  vec3 right, up;
  shadow_quad(base, u_size, u_to_light, u_eye, right, up);
  for (int i = 0; i < 4; ++i) {
    vec2 uv = vec2(i & 1, i >> 1);
    g_uv = uv;
    gl_Position = u_light_view_proj * vec4(base + (uv.x - 0.5) * right + uv.y * up, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
