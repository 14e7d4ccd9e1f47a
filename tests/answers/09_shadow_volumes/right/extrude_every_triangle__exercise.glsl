// right: the course's other construction: every lit triangle extrudes all three edges (no silhouette test), the shared sides cancel
// expect: variant
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  // The course's alternative: every lit triangle extrudes all three edges; the sides of shared edges
  // come once from each neighbour, in opposite orientations, and cancel in the stencil count.
  if (!faces_light(t0, t1, t2)) return;
  emit_side(t0, t1);
  emit_side(t1, t2);
  emit_side(t2, t0);
  if (u_caps) {
    emit_near_cap(t0, t1, t2);
    emit_far_cap(t0, t1, t2);
  }
}
