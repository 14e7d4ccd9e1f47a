#version 330 core
// Lit pass: ambient + Lambert, with the light's term scaled by the shadow test's visibility.
// The shadow test itself comes from "lab/visibility.glsl", which a lab may point at its own file; the
// surface's colour from "lab/material.glsl" (the vertex colour unless a lab gives a material).
//
// Variants (injected defines): LIGHT_SPOT / LIGHT_POINT light from u_light_position (a spot only within
// its cone), else a directional light along u_to_light. With stencil shadow volumes the scene is drawn
// twice: SHADOW_VOLUME_AMBIENT (ambient only, and the G-buffer) and SHADOW_VOLUME_ADDITIVE (the light's
// share, added where the stencil test found no volume).
#define SHADOW_COORDS_FROM_VERTEX  // v_world_position and v_light_tex come from lit.vert
#include "shadow/common.glsl"
#include "lab/visibility.glsl"
#include "lab/material.glsl"
#ifdef SHADOWED_LIGHTS
// Further shadowed lights beside the sun (Features::lights, e.g. lab 15's flashlight): each with its own
// map and test, and the lab's combination of two lights' terms.
#include "shadow/shadowed_lights.glsl"
#include "lab/combine.glsl"
uniform float u_sun_intensity;
#endif

in vec3 v_normal;
in vec3 v_color;
#ifdef MATERIAL_TEXTURE
// Compiled only for scenes with materials (the renderer's MATERIAL_TEXTURE variant): the base-colour
// texture (white for untextured meshes) times the vertex colour; MASK discards below the cutoff
// (u_alpha_cutoff: -1 for OPAQUE, -2 for BLEND, whose alpha goes out with the colour; the others write 1).
in float v_alpha;
in vec2 v_uv;
uniform sampler2D u_base_color;
uniform float u_alpha_cutoff;
#endif

uniform vec3 u_to_light;
uniform float u_ambient;
#ifdef LIGHT_SPOT
uniform vec3 u_spot_direction;  // unit, from the light toward the scene
uniform float u_spot_cos_cone;  // cosine of the cone's half-angle: outside it the spot gives no light
#endif

layout(location = 0) out vec4 o_color;
#ifdef WRITE_GBUFFER
// For the oracle: visibility, world position (w = 1 marks covered pixels) and normal per pixel.
layout(location = 1) out float o_visibility;
layout(location = 2) out vec4 o_position;
layout(location = 3) out vec4 o_normal;
#endif

vec3 light_vector(vec3 p) {
#if defined(LIGHT_SPOT) || defined(LIGHT_POINT)
  return normalize(u_light_position - p);
#else
  return u_to_light;
#endif
}

bool reached_by_light(vec3 p) {
#ifdef LIGHT_SPOT
  return dot(normalize(p - u_light_position), u_spot_direction) >= u_spot_cos_cone;
#else
  return true;
#endif
}

vec3 encode(vec3 linear) { return pow(linear, vec3(1.0 / 2.2)); }

void main() {
  // Shade both sides of thin or open geometry: the side facing the camera is the one we see.
#ifdef MATERIAL_TEXTURE
  vec4 texel = texture(u_base_color, v_uv);
  float alpha = v_alpha * texel.a;
  if (alpha < u_alpha_cutoff) discard;
  vec3 base = v_color * texel.rgb;
  if (u_alpha_cutoff > -1.5) alpha = 1.0;
#else
  const float alpha = 1.0;
  vec3 base = v_color;
#endif
  vec3 n = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
  float n_dot_l = reached_by_light(v_world_position) ? dot(n, light_vector(v_world_position)) : 0.0;
  float visibility = n_dot_l > 0.0 ? shadow_visibility(v_world_position, n, n_dot_l) : 0.0;
  vec3 albedo = surface_albedo(v_world_position, n, base);  // the lab's material over the base colour
  vec3 ambient = albedo * u_ambient;
#ifdef SHADOWED_LIGHTS
  // The loop over the lights, unrolled (each map's sampler indexed by a constant): the sun and light 0 as
  // the lab's combine_lights says, then each further light combined with the light so far, which stands in
  // as a light fully lit (with the sum, the default, every light's term times its own shadow term added).
  float light_shadow;
  float light_lambert = shadowed_light_terms(0, u_light_maps[0], v_world_position, n, light_shadow);
  float direct = combine_lights(u_sun_intensity * max(n_dot_l, 0.0), visibility, light_lambert, light_shadow);
#define COMBINE_SHADOWED_LIGHT(i) light_lambert = shadowed_light_terms(i, u_light_maps[i], v_world_position, n, light_shadow); direct = combine_lights(direct, 1.0, light_lambert, light_shadow);
#if SHADOWED_LIGHTS > 1
  COMBINE_SHADOWED_LIGHT(1)
#endif
#if SHADOWED_LIGHTS > 2
  COMBINE_SHADOWED_LIGHT(2)
#endif
#if SHADOWED_LIGHTS > 3
  COMBINE_SHADOWED_LIGHT(3)
#endif
  vec3 linear = ambient + albedo * (1.0 - u_ambient) * direct;
#else
  vec3 linear = ambient + albedo * (1.0 - u_ambient) * max(n_dot_l, 0.0) * visibility;
#endif
#if defined(SHADOW_VOLUME_AMBIENT)
  visibility = 0.0;  // the additive pass adds 1 where the light reaches
  o_color = vec4(encode(ambient), 1.0);
#elif defined(SHADOW_VOLUME_ADDITIVE)
  // Blended with ONE, ONE onto the ambient pass. The framebuffer holds gamma-encoded colour, so the
  // light's share is the difference of the encoded sums: ambient + this = encode(ambient + diffuse).
  o_color = vec4(encode(linear) - encode(ambient), 0.0);
#else
  o_color = vec4(encode(linear), alpha);
#ifdef TECHNIQUE_VIEW
  // A shadow test's own debug view (e.g. shaders/shadow/pcss.glsl's pcss.view): what it found, as colour.
  vec3 seen;
  if (technique_view(n_dot_l > 0.0, seen)) o_color = vec4(seen, 1.0);
#endif
#endif
#ifdef WRITE_GBUFFER
#ifdef SHADOWED_LIGHTS
  o_visibility = direct;  // several lights: the direct light the lab's combination returned (what lab 15 grades)
#else
  o_visibility = visibility;
#endif
  o_position = vec4(v_world_position, 1.0);
  o_normal = vec4(n, 0.0);
#endif
}
