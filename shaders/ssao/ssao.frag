#version 330 core
// Screen-space ambient occlusion (renderer/ssao_pass.h): per pixel, the share of the kernel's samples
// that the depth buffer does not hide, computed by ssao_open() from "lab/ssao.glsl" (lab 17's exercise;
// the solution is shaders/ssao/ssao_core.glsl). Writes 1 (open) where no surface was drawn.
in vec2 v_uv;
out float o_open;

uniform sampler2D u_position;  // view space, w = 1 where covered
uniform sampler2D u_normal;    // view space, unit
uniform sampler2D u_noise;     // 4 x 4 vectors in the tangent plane (z = 0), repeat-wrapped
uniform vec2 u_noise_scale;    // the frame's size over the noise texture's: one texel per pixel
uniform bool u_use_noise;
uniform mat4 u_projection;     // view -> clip, the frame's
uniform mat4 u_view;           // world -> view (positions and normals here are already in view space)
uniform vec3 u_kernel[64];  // points of the unit hemisphere z >= 0, unscaled
uniform int u_samples;
uniform float u_radius;
uniform float u_bias;
uniform bool u_range_check;

// The kernel's i-th sample (i < ssao_sample_count()), in tangent space: z along the normal, inside the
// unit hemisphere (z >= 0), scaled toward its centre by lerp(0.1, 1, (i / count)^2) (LearnOpenGL's scale,
// over the samples taken: most samples lie near the point, where occluders matter most).
vec3 ssao_kernel(int i) {
  float t = float(i) / float(u_samples);
  return u_kernel[i] * mix(0.1, 1.0, t * t);
}
int ssao_sample_count() { return u_samples; }

// The view-space z of the surface the depth buffer holds where the view-space point p projects (the
// visible surface along the ray from the eye through p); a very far z (-1e6) outside the frame or where
// no surface was drawn.
float ssao_scene_depth(vec3 p) {
  vec4 clip = u_projection * vec4(p, 1.0);
  vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
  if (clip.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return -1e6;
  vec4 q = texture(u_position, uv);
  return q.w > 0.5 ? q.z : -1e6;
}

#include "lab/ssao.glsl"

void main() {
  vec4 p = texture(u_position, v_uv);
  if (p.w < 0.5) {
    o_open = 1.0;
    return;
  }
  vec3 n = normalize(texture(u_normal, v_uv).xyz);
  vec3 noise = u_use_noise ? texture(u_noise, v_uv * u_noise_scale).xyz : vec3(1.0, 0.0, 0.0);
  o_open = clamp(ssao_open(p.xyz, n, noise, u_radius, u_bias, u_range_check), 0.0, 1.0);
}
