// wrong: writes part 1 (the distance) and leaves part 2 as handed out: everything lit
// expect: skipped-half
// fails: faces.wrong_face bias.too_small
uniform sampler2DArray u_shadow_faces;  // the six faces: layers 0-5 = +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // the angle one texel spans at a face's centre (2 / size), in radians
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)

const float MAX_TAN_INCIDENCE = 10.0;

float stored_distance(vec3 d) {
  return texture(u_shadow_faces, vec3(0.5, 0.5, 0.0)).r;
}

float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  return 1.0;
}
