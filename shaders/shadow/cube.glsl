// The point light's shadow test (lab 8's solution, part 2). The shadow pass stored, per texel of six
// 90-degree faces, the distance from the light to the nearest surface. Select the face and the texel the
// direction from the light to the fragment passes through, and compare the fragment's own distance with
// the stored one. 1 lit, 0 shadowed.
uniform sampler2DArray u_shadow_faces;  // layers 0-5: the faces +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // angle one texel spans at a face's centre (2 / size)
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)
// tan(angle of incidence), capped: it grows without bound at grazing light, and past 10 the bias would lift
// whole shadows. Written here, not included: this file is also lab 8's exercise slot, which includes nothing.
float cube_tan_incidence(float n_dot_l) { return min(sqrt(max(1.0 - n_dot_l * n_dot_l, 0.0)) / n_dot_l, 10.0); }

// One texel's worth of distance is always subtracted: the stored distance belongs to the texel's centre
// direction, not the fragment's.
const float CONSTANT_TEXELS = 1.0;

// Face selection, as the GL specification defines it for cube maps: the component of largest magnitude
// picks the face (its sign: + or -), the other two, divided by it, give the place on the face in
// [-1, 1], oriented as the face was rendered (point_light_views: t runs down the side faces).
float stored_distance(vec3 d) {
  vec3 a = abs(d);
  float face, sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    ma = a.x;
    face = d.x > 0.0 ? 0.0 : 1.0;
    sc = d.x > 0.0 ? -d.z : d.z;
    tc = -d.y;
  } else if (a.y >= a.z) {
    ma = a.y;
    face = d.y > 0.0 ? 2.0 : 3.0;
    sc = d.x;
    tc = d.y > 0.0 ? d.z : -d.z;
  } else {
    ma = a.z;
    face = d.z > 0.0 ? 4.0 : 5.0;
    sc = d.z > 0.0 ? d.x : -d.x;
    tc = -d.y;
  }
  vec2 st = 0.5 * vec2(sc, tc) / ma + 0.5;  // [-1, 1] on the face -> [0, 1] texture coordinates
  return texture(u_shadow_faces, vec3(st, face)).r;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  vec3 from_light = world_position - u_light_position;  // the faces were rendered from the light outward
  float distance_to_light = length(from_light);
  float stored = stored_distance(from_light);
  float texel_world = distance_to_light * u_texel_angle;  // a texel's footprint at this distance
  float bias = texel_world * (CONSTANT_TEXELS + u_bias_slope * cube_tan_incidence(n_dot_l));
  return distance_to_light - bias > stored ? 0.0 : 1.0;
}
