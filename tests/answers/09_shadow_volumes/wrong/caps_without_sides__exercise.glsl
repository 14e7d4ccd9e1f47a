// wrong: does the caps (the lit triangle and its reversed copy at infinity) and leaves the silhouette sides out
// expect: skipped-half
// fails: *zpass.interior_agreement
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (u_caps) {
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
