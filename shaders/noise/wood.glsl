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
  // After the PGR lecture's wood (Brno University of Technology, FIT): its smoothstep(0.2, 0.4) of the
  // ring fraction between its two browns, RGB (140, 90, 27) and (188, 140, 42) / 255. Two numbers are
  // this lab's, not the lecture's (lab 10's README says why): the rings per world unit (noise.rings, 3;
  // the lecture's 10 count per unit of its small object, the floor here is 12 units wide) and the
  // perturbation, added to the ring count (noise.turbulence rings) instead of 0.1 x noise added to the
  // position before its length.
  float r = length(p.xz) * u_wood_rings + u_wood_turbulence * noise_octaves(q);
  float t = smoothstep(0.2, 0.4, fract(r));
  return mix(vec3(140.0, 90.0, 27.0) / 255.0, vec3(188.0, 140.0, 42.0) / 255.0, t);
}
