// wrong: draws the caps when u_caps is false (z-pass) and leaves them out for z-fail
// expect: sign
// fails: *zfail.interior_agreement
// One side of the volume: the edge a -> b, as the lit triangle runs it, swept to infinity.
void side(vec3 a, vec3 b) {
  emit(vec4(a, 1.0));
  emit(at_infinity(a));
  emit(vec4(b, 1.0));
  emit(at_infinity(b));
  EndPrimitive();
}

void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (!faces_light(t0, n01, t1)) side(t0, t1);
  if (!faces_light(t1, n12, t2)) side(t1, t2);
  if (!faces_light(t2, n20, t0)) side(t2, t0);
  if (!u_caps) {
    emit(vec4(t0, 1.0));
    emit(vec4(t1, 1.0));
    emit(vec4(t2, 1.0));
    EndPrimitive();
    if (!directional_light()) {
      emit(at_infinity(t0));
      emit(at_infinity(t2));
      emit(at_infinity(t1));
      EndPrimitive();
    }
  }
}
