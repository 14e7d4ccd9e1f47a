#version 330 core
// A point light's shadow pass: what each texel of the six faces stores, decided by
// "lab/cube_store.glsl" (lab 8's exercise; the renderer's own is shaders/cube/store.glsl). The depth
// buffer only picks the surface nearest the light along each texel's direction.
in vec3 v_world_position;
uniform vec3 u_light_position;
layout(location = 0) out float o_distance;

#include "lab/cube_store.glsl"
// An alpha-tested caster (the ALPHA_MASK variant) discards where the view does.
#include "shadow/alpha_mask.glsl"

void main() {
  alpha_test();
  o_distance = value_to_store(v_world_position);
}
