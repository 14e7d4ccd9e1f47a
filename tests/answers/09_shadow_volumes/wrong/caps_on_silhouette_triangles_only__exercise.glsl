// wrong: caps only the triangles that emitted a side ('they are the ones with a volume'): the caps have holes
// expect: structure
// fails: *zfail.interior_agreement
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  bool silhouette = false;
  if (!faces_light(t0, n01, t1)) { emit_side(t0, t1); silhouette = true; }
  if (!faces_light(t1, n12, t2)) { emit_side(t1, t2); silhouette = true; }
  if (!faces_light(t2, n20, t0)) { emit_side(t2, t0); silhouette = true; }
  // only triangles on the silhouette have a volume to close
  if (u_caps && silhouette) {
    emit_near_cap(t0, t1, t2);
    emit_far_cap(t0, t1, t2);
  }
}
