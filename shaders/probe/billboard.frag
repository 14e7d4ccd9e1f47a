#version 330 core
// Grading probe (grading/probe.h): runs lab 11's shadow_quad and shadow_keeps on chosen inputs, one
// fragment per case. u_probe_in1.w < 0: shadow_keeps(uv = in0.xy, cutoff = in0.z), 1 kept, 0 not.
// Else shadow_quad(base = in0.xyz, u_probe_size, to_light = in1.xyz, u_probe_eye), and the result is
// component in1.w of (right.xyz, up.xyz).
#include "billboard/shape.glsl"
#include "lab/billboard.glsl"

uniform sampler2D u_probe_in0;
uniform sampler2D u_probe_in1;
uniform vec3 u_probe_eye;
uniform vec3 u_probe_size;  // width, height (z unused)

out vec4 o_result;

void main() {
  vec4 a = texelFetch(u_probe_in0, ivec2(gl_FragCoord.xy), 0);
  vec4 b = texelFetch(u_probe_in1, ivec2(gl_FragCoord.xy), 0);
  float v;
  if (b.w < 0.0) {
    v = shadow_keeps(a.xy, a.z) ? 1.0 : 0.0;
  } else {
    vec3 right, up;
    shadow_quad(a.xyz, u_probe_size.xy, b.xyz, u_probe_eye, right, up);
    int k = int(b.w + 0.5);
    v = k < 3 ? right[k] : up[k - 3];
  }
  o_result = vec4(v, 0.0, 0.0, 1.0);
}
