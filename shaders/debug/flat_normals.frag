#version 330 core
// Flat normals view: each triangle in the colour of its face normal (x red, y green, z blue; 0.5 + 0.5 n),
// so every facet of a smooth-shaded mesh shows as one flat colour.
in vec3 v_face_normal;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(0.5 + 0.5 * v_face_normal, 1.0); }
