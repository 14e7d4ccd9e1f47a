// right: s, t and the layer packed in one vec3 per face, the largest magnitude found with max(), comparison written as stored < distance - bias
// expect: variant
uniform sampler2DArray u_shadow_faces;  // the six faces: layers 0-5 = +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // the angle one texel spans at a face's centre (2 / size), in radians
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

// Sign first, then magnitude: the same table in another order.
float stored_distance(vec3 d) {
  vec3 a = abs(d);
  float m = max(a.x, max(a.y, a.z));
  vec3 st_face;
  if (m == a.x) st_face = d.x > 0.0 ? vec3(-d.z, -d.y, 0.0) : vec3(d.z, -d.y, 1.0);
  else if (m == a.y) st_face = d.y > 0.0 ? vec3(d.x, d.z, 2.0) : vec3(d.x, -d.z, 3.0);
  else st_face = d.z > 0.0 ? vec3(d.x, -d.y, 4.0) : vec3(-d.x, -d.y, 5.0);
  return texture(u_shadow_faces, vec3((st_face.xy / m + 1.0) / 2.0, st_face.z)).r;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 from_light = world_position - u_light_position;
  float distance_to_light = length(from_light);
  float stored = stored_distance(-(u_light_position - world_position));
  float texel_world = distance_to_light * u_texel_angle;
  float tan_incidence = min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, MAX_TAN_INCIDENCE);
  float bias = texel_world * (1.0 + u_bias_slope * tan_incidence);
  return stored < distance_to_light - bias ? 0.0 : 1.0;
}
