// wrong: compares the squared distance (dot(v, v), to save the sqrt) with the stored distance
// expect: units
// fails: bias.*
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
  float bias = texel_world * (1.0 + u_bias_slope * tan_incidence);
  return dot(from_light, from_light) - bias > stored ? 0.0 : 1.0;
}
