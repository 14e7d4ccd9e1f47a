// wrong: adds the far cap for z-fail but not the near cap ('the occluder itself closes the volume')
// expect: skipped-half
// fails: *zfail.interior_agreement
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
  if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
  if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  if (u_caps) emit_far_cap(t0, t1, t2);
}
