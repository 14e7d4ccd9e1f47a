// wrong: writes the comparison and leaves the stock's face selection (the middle of +X for every direction)
// expect: skipped-half
// fails: faces.wrong_face
uniform sampler2DArray u_shadow_faces;  // the six faces: layers 0-5 = +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // the angle one texel spans at a face's centre (2 / size), in radians
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

float stored_distance(vec3 d) {
  return texture(u_shadow_faces, vec3(0.5, 0.5, 0.0)).r;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 from_light = world_position - u_light_position;
  float distance_to_light = length(from_light);
  float stored = stored_distance(from_light);
  float texel_world = distance_to_light * u_texel_angle;
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
  float bias = texel_world * (1.0 + u_bias_slope * tan_incidence);
  return distance_to_light - bias > stored ? 0.0 : 1.0;
}
