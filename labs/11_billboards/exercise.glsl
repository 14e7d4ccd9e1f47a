// Lab 11: the shadows of billboards.
//
// Each tree is a point; a geometry shader makes it a quad standing upright on the point. The view turns
// the quad toward the camera. The shadow pass draws the quad this file builds, and keeps the points this
// file keeps. Both functions below still do what the view does: the quad faces the camera, and nothing
// is cut out.

// The shadow pass's quad for the tree standing at `base`: `right` across it (size.x long) and `up` from
// its foot to its top (size.y long), in world units. to_light: unit vector toward the light (directional);
// eye: the camera's position.
void shadow_quad(vec3 base, vec2 size, vec3 to_light, vec3 eye, out vec3 right, out vec3 up) {
  // TODO: the view's quad, turned toward the camera. What does the light see?
  vec3 to_eye = eye - base;
  right = normalize(vec3(to_eye.z, 0.0, -to_eye.x)) * size.x;
  up = vec3(0.0, size.y, 0.0);
}

// Whether the shadow map keeps this point of the quad (uv: (0, 0) bottom left, (1, 1) top right).
// billboard_alpha(uv) is the tree's alpha there; the view cuts out every point below `cutoff`.
bool shadow_keeps(vec2 uv, float cutoff) {
  // TODO: the alpha test.
  return true;
}
