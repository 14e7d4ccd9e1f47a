#version 330 core
// Debug quad of one face of a point light's distance cube: near dark, far light, empty texels white.
// The direction through (s, t) of each face follows the GL spec's cube-map face table (t runs down the
// face image, so the quad's top row is t = -1).
in vec2 v_uv;
uniform samplerCube u_cube;
uniform int u_face;   // 0..5: +X, -X, +Y, -Y, +Z, -Z
uniform float u_far;  // the largest distance the faces store (the fitted far plane)
out vec4 o_color;

vec3 face_direction(int face, float s, float t) {
  if (face == 0) return vec3(1.0, -t, -s);
  if (face == 1) return vec3(-1.0, -t, s);
  if (face == 2) return vec3(s, 1.0, t);
  if (face == 3) return vec3(s, -1.0, -t);
  if (face == 4) return vec3(s, -t, 1.0);
  return vec3(-s, -t, -1.0);
}

void main() {
  float s = v_uv.x * 2.0 - 1.0, t = 1.0 - v_uv.y * 2.0;
  float d = texture(u_cube, face_direction(u_face, s, t)).r;
  o_color = vec4(vec3(d >= 1e29 ? 1.0 : clamp(d / u_far, 0.0, 1.0) * 0.9), 1.0);
}
