#version 330 core
// Debug quad of one face of a point light's distance faces: near dark, far light, empty texels white.
// Shown as the face was rendered (point_light_views): texture row 0 at the quad's top, as a cube map's
// t axis runs down the face image.
in vec2 v_uv;
uniform sampler2DArray u_cube;
uniform int u_face;   // 0..5: +X, -X, +Y, -Y, +Z, -Z
uniform float u_far;  // the largest distance the faces store (the fitted far plane)
out vec4 o_color;

void main() {
  float d = texture(u_cube, vec3(v_uv.x, 1.0 - v_uv.y, float(u_face))).r;
  o_color = vec4(vec3(d >= 1e29 ? 1.0 : clamp(d / u_far, 0.0, 1.0) * 0.9), 1.0);
}
