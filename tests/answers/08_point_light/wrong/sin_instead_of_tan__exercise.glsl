// wrong: the slope term from sin of the incidence instead of tan: half of tan at 60 degrees, but never above 1 where tan grows at grazing light
// expect: compile-fine-but-wrong-formula
// fails: bias.too_small
uniform sampler2DArray u_shadow_faces;  // the six faces: layers 0-5 = +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // the angle one texel spans at a face's centre (2 / size), in radians
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

float stored_distance(vec3 d) {
  vec3 a = abs(d);
  float face, s, t, m;
  if (a.x >= a.y && a.x >= a.z) {
    m = a.x;
    face = d.x > 0.0 ? 0.0 : 1.0;
    s = d.x > 0.0 ? -d.z : d.z;
    t = -d.y;
  } else if (a.y >= a.z) {
    m = a.y;
    face = d.y > 0.0 ? 2.0 : 3.0;
    s = d.x;
    t = d.y > 0.0 ? d.z : -d.z;
  } else {
    m = a.z;
    face = d.z > 0.0 ? 4.0 : 5.0;
    s = d.z > 0.0 ? d.x : -d.x;
    t = -d.y;
  }
  return texture(u_shadow_faces, vec3(0.5 * vec2(s, t) / m + 0.5, face)).r;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 from_light = world_position - u_light_position;
  float distance_to_light = length(from_light);
  float stored = stored_distance(from_light);
  float texel_world = distance_to_light * u_texel_angle;
  float sin_incidence = sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0));  // 'the slope: how far the surface leans'
  float bias = texel_world * (1.0 + u_bias_slope * sin_incidence);
  return distance_to_light - bias > stored ? 0.0 : 1.0;
}
