#version 330 core
// Ground-truth-based ambient occlusion (GTAO, Jimenez, Wu, Pesce and Jarabo 2016), the AO pass's second
// method (ssao.method = gtao; renderer/ssao_pass.h): per pixel, gtao_open() of "ao/gtao.glsl" (default
// shaders/ssao/gtao_core.glsl) on the same view-space G-buffer as SSAO. Writes 1 (open) where no surface
// was drawn, like shaders/ssao/ssao.frag, so the blur and the composite serve both methods.
in vec2 v_uv;
out float o_open;

uniform sampler2D u_position;  // view space, w = 1 where covered
uniform sampler2D u_normal;    // view space, unit
uniform sampler2D u_noise;     // 4 x 4 vectors in the screen plane, repeat-wrapped
uniform vec2 u_noise_scale;    // the frame's size over the noise texture's: one texel per pixel
uniform bool u_use_noise;
uniform mat4 u_projection;     // view -> clip, the frame's
uniform int u_directions;      // slices per pixel
uniform int u_steps;           // depth samples on each side of a slice
uniform float u_radius;

const float kPi = 3.14159265358979;

// The view-space point drawn at uv, w = 0 where nothing was (or outside the frame).
vec4 gtao_position(vec2 uv) {
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return vec4(0.0);
  return texture(u_position, uv);
}

#include "ao/gtao.glsl"

void main() {
  vec4 p = texture(u_position, v_uv);
  if (p.w < 0.5) {
    o_open = 1.0;
    return;
  }
  vec3 n = normalize(texture(u_normal, v_uv).xyz);
  // Per-pixel offsets of the slices' angle and of the steps, from the 4 x 4 noise (both in [0, 1)).
  vec2 jitter = vec2(0.0, 0.5);
  if (u_use_noise) {
    vec2 r = texture(u_noise, v_uv * u_noise_scale).xy;
    jitter = vec2(atan(r.y, r.x) / (2.0 * kPi) + 0.5, fract(4.0 * length(r)));
  }
  o_open = clamp(gtao_open(v_uv, p.xyz, n, jitter), 0.0, 1.0);
}
