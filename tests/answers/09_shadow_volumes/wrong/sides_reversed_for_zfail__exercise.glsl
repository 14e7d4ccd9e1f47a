// wrong: reverses the side quads for z-fail ('it counts the other way round') as well as adding the caps
// expect: sign
// fails: *zfail.interior_agreement
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (u_caps) {
    // z-fail counts back faces +1: turn the sides around
    if (!faces_light(t0, n01, t1)) emit_side(t1, t0);
    if (!faces_light(t1, n12, t2)) emit_side(t2, t1);
    if (!faces_light(t2, n20, t0)) emit_side(t0, t2);
    emit_near_cap(t0, t1, t2);
    emit_far_cap(t0, t1, t2);
  } else {
    if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
    if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
    if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  }
}
