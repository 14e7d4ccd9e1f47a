// Lab 8 exercise, part 2: the point light's shadow test, in the lit pass. Edit this file; the lab reloads
// it when you save.
uniform sampler2DArray u_shadow_faces;  // the six faces: layers 0-5 = +X, -X, +Y, -Y, +Z, -Z
uniform float u_texel_angle;  // the angle one texel spans at a face's centre (2 / size), in radians
uniform float u_bias_slope;   // slider "Slope bias", in texels per unit of tan(angle of incidence)
// Also available: u_light_position (world space).

// Face selection: what the shadow pass stored for direction d (not normalised) from the light. Read it
// with texture(u_shadow_faces, vec3(s, t, layer)), s and t in [0, 1]. Keep the name and the signature:
// the check calls this function on its own.
float stored_distance(vec3 d) {
  // TODO: the faces were rendered as the faces of a GL cube map, each a 90-degree view in GL's face
  // order and orientation. Pick the face and the place on it that direction d passes through, by the
  // rule GL uses for cube maps. This reads the middle of the +X face, whatever d is.
  return texture(u_shadow_faces, vec3(0.5, 0.5, 0.0)).r;
}

// Returns 1 where the light reaches the point, 0 where something nearer to the light hides it.
float shadow_visibility(vec3 world_position, vec3 n, float n_dot_l) {
  // TODO: compare the fragment with what the shadow pass stored in its direction, with a bias in world
  // units that covers a texel's footprint at the fragment's distance and grows with the slope (lab 1's
  // slope term). Everything is lit until you do. Then run: shadowlab check --lab 8 --impl exercise
  return 1.0;
}
