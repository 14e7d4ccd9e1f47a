// Lab 7 exercise: the spot light's shadow test. Edit this file; the lab reloads it when you save.
// shadow_bias(n_dot_l): the directional labs' bias in depth units, lab 1's constant (slider "Constant bias")
// plus its slope term; and
// u_bias_slope (slider "Slope bias", in texels per unit of tan(angle of incidence)).
#include "lab/bias.glsl"

uniform float u_light_near;   // the spot's fitted near and far planes (world units along its axis)
uniform float u_light_far;
uniform float u_texel_angle;  // one texel's world size per unit of distance: 2 tan(cone) / map size

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  // The spot's matrix is a perspective projection: after the divide by w, s.z is a window depth in
  // [0, 1] that is NOT proportional to the distance from the light.
  vec3 s = shadow_coords(world_position);
  if (outside_shadow_map(s)) return 1.0;
  float closest = texture(u_shadow_map, s.xy).r;
  // TODO: this is lab 0's test, a constant bias in depth units. With an orthographic light one depth
  // unit is the same distance everywhere; here d = f/(f-n) * (1 - n/z), so the same 0.005 is a hair
  // near the light and a long way far from it. Turn both depths back into distances along the light's
  // axis (invert the projection using u_light_near and u_light_far), and bias by a distance that grows
  // with a texel's footprint there (z * u_texel_angle) and with the slope. Then run:
  //   shadowlab check --lab 7 --impl exercise
  return s.z - shadow_bias(n_dot_l) > closest ? 0.0 : 1.0;
}
