// What one triangle contributes to its mesh's shadow volume (lab 9's solution).
//   t0, t1, t2: the triangle (counter-clockwise from its front);
//   n01, n12, n20: the far vertex of the neighbouring triangle across each edge. An open edge (the
//   lecture's "bad geometry") has the triangle's own opposite vertex there, so it always counts as a
//   silhouette and the volume stays closed on that side.
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  // 1. Only triangles facing the light emit: every silhouette edge then comes from its lit side, once.
  if (!faces_light(t0, t1, t2)) return;
  // 2. A silhouette edge: the neighbour across it faces away. Its quad runs to infinity (w = 0).
  if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
  if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
  if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  // 3. Caps: z-fail counts the faces behind a surface, all the way to infinity, so every volume must be
  // closed: the lit triangles at the near end, the same triangles at infinity at the far end.
  if (u_caps) {
    emit_near_cap(t0, t1, t2);
    emit_far_cap(t0, t1, t2);
  }
}
