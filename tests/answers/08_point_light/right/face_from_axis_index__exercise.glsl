// right: picks the layer as 2 x axis + (negative ? 1 : 0), s and t per axis; the comparison unchanged
// expect: variant
uniform sampler2DArray u_shadow_faces;  // the six faces: layers 0-5 = +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // the angle one texel spans at a face's centre (2 / size), in radians
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

// The face's axis index and sign pick the layer; GL's table gives s and t per face as (sign, component).
float stored_distance(vec3 d) {
  vec3 a = abs(d);
  int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  bool positive = d[axis] > 0.0;
  int layer = 2 * axis + (positive ? 0 : 1);
  vec2 st;
  if (axis == 0) st = vec2(positive ? -d.z : d.z, -d.y);
  else if (axis == 1) st = vec2(d.x, positive ? d.z : -d.z);
  else st = vec2(positive ? d.x : -d.x, -d.y);
  st = st / a[axis] * 0.5 + 0.5;
  return texture(u_shadow_faces, vec3(st, float(layer))).r;
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
