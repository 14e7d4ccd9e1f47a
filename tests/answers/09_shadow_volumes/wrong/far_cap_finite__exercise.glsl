// wrong: builds the far cap 100 units out instead of at infinity, while the sides run to infinity: the volume is not closed
// expect: structure
// fails: *zfail.interior_agreement
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
  if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
  if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  if (u_caps) {
    emit_near_cap(t0, t1, t2);
    // far cap: the triangle pushed 100 units away from the light
    vec3 f0 = t0 - 100.0 * normalize(toward_light(t0));
    vec3 f1 = t1 - 100.0 * normalize(toward_light(t1));
    vec3 f2 = t2 - 100.0 * normalize(toward_light(t2));
    emit(vec4(f0, 1.0));
    emit(vec4(f2, 1.0));
    emit(vec4(f1, 1.0));
    EndPrimitive();
  }
}
