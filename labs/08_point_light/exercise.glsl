// Lab 8 exercise: the point light's shadow test against a cube map. Edit this file; the lab reloads it
// when you save.
uniform samplerCube u_shadow_cube;  // per direction from the light: distance to the nearest surface
uniform float u_texel_angle;  // angle one texel spans at a face's centre (2 / size)
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  // The lighting already needs the vector toward the light, so the first attempt reuses it.
  vec3 to_light = u_light_position - world_position;
  float distance_to_light = length(to_light);
  // TODO: a cube map is addressed by a direction from its centre, and the shadow pass looked from the
  // light outward. Which way must this vector point? Look at the debug picture (--out) of the
  // exercise: whose shadows appear where? Then run: shadowlab check --lab 8 --impl exercise
  float stored = texture(u_shadow_cube, to_light).r;
  float texel_world = distance_to_light * u_texel_angle;
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
  float bias = texel_world * (1.0 + u_bias_slope * tan_incidence);
  return distance_to_light - bias > stored ? 0.0 : 1.0;
}
