// Lab 9 exercise: what one triangle contributes to its mesh's shadow volume. Edit this file; the lab
// reloads it when you save.
//   t0, t1, t2: the triangle (counter-clockwise from its front);
//   n01, n12, n20: the far vertex of the neighbouring triangle across each edge (GL_TRIANGLES_ADJACENCY).
// Helpers from shaders/volume/extrude.geom: faces_light(a, b, c), emit_side(a, b) (a quad from edge
// a -> b to infinity), emit_near_cap(a, b, c), emit_far_cap(a, b, c), at_infinity(p), emit(world),
// and the uniform u_caps (true when the stencil counting is z-fail).
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  // 1. Only triangles facing the light emit: every silhouette edge then comes from its lit side, once.
  if (!faces_light(t0, t1, t2)) return;
  // 2. A silhouette edge: the neighbour across it faces away. Its quad runs to infinity (w = 0).
  if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
  if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
  if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  // TODO: these open-ended volumes are all z-pass needs, as long as the camera stays outside every
  // volume. z-fail (Carmack's reverse) counts the faces *behind* each surface out to infinity, so each
  // volume must be closed: add a near cap and a far cap when u_caps is set. Then run
  //   shadowlab check --lab 9 --impl exercise
  // and compare the pictures with the camera inside a volume (--out).
}
