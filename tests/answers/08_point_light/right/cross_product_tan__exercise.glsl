// right: tan of the incidence from |n x l| / (n . l), lookup with the unit vector, step() for the comparison
// expect: variant
uniform samplerCube u_shadow_cube;  // per direction from the light: distance to the nearest surface
uniform float u_texel_angle;  // angle one texel spans at a face's centre (2 / size)
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 light_to_point = world_position - u_light_position;
  float d = length(light_to_point);
  float stored = texture(u_shadow_cube, light_to_point / d).r;
  // tan from the cross product's length: |n x l| / (n . l)
  vec3 l = -light_to_point / d;
  float tan_incidence = min(length(cross(n, l)) / max(n_dot_l, 1e-4), MAX_TAN_INCIDENCE);
  float texels = 1.0 + u_bias_slope * tan_incidence;
  return step(d - texels * d * u_texel_angle, stored);
}
