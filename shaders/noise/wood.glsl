// Lab 10's material ("lab/material.glsl"): the floor is wood, rings around the origin perturbed by the
// octave sum of the lab's gradient noise ("lab/noise.glsl"); every other surface keeps its colour.
// Debug views (noise.view): 1 the noise, 2 the octave sum, 3 the three octaves as red, green, blue
// (grey = 0.5 + 0.5 value).
#include "lab/noise.glsl"

uniform float u_floor_height;     // the scene's lowest y: the floor
uniform float u_noise_scale;      // noise.scale: noise units per world unit
uniform float u_wood_rings;       // noise.rings: rings per world unit
uniform float u_wood_turbulence;  // noise.turbulence: how far (in rings) the noise pushes them
uniform float u_noise_view;       // noise.view

vec3 surface_albedo(vec3 p, vec3 n, vec3 color) {
  if (n.y < 0.99 || p.y > u_floor_height + 1e-3) return color;
  vec2 q = p.xz * u_noise_scale;
  int view = int(u_noise_view + 0.5);
  if (view == 1) return vec3(0.5 + 0.5 * gradient_noise(q));
  if (view == 2) return vec3(0.5 + 0.5 * noise_octaves(q));
  if (view == 3)
    return 0.5 + 0.5 * vec3(gradient_noise(q), 0.5 * gradient_noise(2.0 * q), 0.25 * gradient_noise(4.0 * q));
  // The lecture's wood: rings fract(10 |p|), perturbed, a smoothstep between two browns.
  float r = length(p.xz) * u_wood_rings + u_wood_turbulence * noise_octaves(q);
  float t = smoothstep(0.2, 0.4, fract(r));
  return mix(vec3(0.36, 0.20, 0.09), vec3(0.72, 0.50, 0.28), t);
}
