#version 330 core
// The view's billboards: each point becomes a quad standing upright on it and turned about the vertical
// toward the camera (a cylindrical billboard: trees stay upright).
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 v_base[];
out vec2 g_uv;
uniform mat4 u_view_proj;
uniform vec3 u_eye;   // the camera's position
uniform vec2 u_size;  // width, height

void main() {
  vec3 base = v_base[0];
  vec3 to_eye = u_eye - base;
  vec3 across = vec3(to_eye.z, 0.0, -to_eye.x);  // horizontal, perpendicular to the view
  vec3 right = (dot(across, across) > 1e-12 ? normalize(across) : vec3(1.0, 0.0, 0.0)) * u_size.x;
  vec3 up = vec3(0.0, u_size.y, 0.0);
  for (int i = 0; i < 4; ++i) {
    vec2 uv = vec2(i & 1, i >> 1);
    g_uv = uv;
    gl_Position = u_view_proj * vec4(base + (uv.x - 0.5) * right + uv.y * up, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
