#version 330 core
// Grading probe (grading/probe.h): runs a lab's shadow_visibility() on chosen inputs instead of a scene,
// one fragment per case, with the same includes as the lit pass (shaders/lit.frag) and the uniforms the
// check sets. Inputs per case: u_probe_in0 = (world position, n . l), u_probe_in1 = (normal, unused).
#include "shadow/common.glsl"
#include "lab/visibility.glsl"

uniform sampler2D u_probe_in0;
uniform sampler2D u_probe_in1;

out vec4 o_result;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 a = texelFetch(u_probe_in0, texel, 0);
  vec4 b = texelFetch(u_probe_in1, texel, 0);
  o_result = vec4(shadow_visibility(a.xyz, b.xyz, a.w), 0.0, 0.0, 1.0);
}
