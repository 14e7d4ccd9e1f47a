// wrong: a hand-tuned constant bias of 0.03 world units (0.02 still failed) instead of one that grows with distance and slope
// expect: tuned-to-scene
// fails: bias.not_proportional
uniform samplerCube u_shadow_cube;  // per direction from the light: distance to the nearest surface
uniform float u_texel_angle;  // angle one texel spans at a face's centre (2 / size)
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 from_light = world_position - u_light_position;
  float distance_to_light = length(from_light);
  float stored = texture(u_shadow_cube, from_light).r;
  float texel_world = distance_to_light * u_texel_angle;
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
  float bias = 0.03;  // 0.02 left a little acne; 0.03 passes
  return distance_to_light - bias > stored ? 0.0 : 1.0;
}
