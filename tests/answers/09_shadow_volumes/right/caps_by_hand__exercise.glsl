// right: writes both caps with emit() and at_infinity() instead of the cap helpers
// expect: variant
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
  if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
  if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  if (!u_caps) return;
  // near cap: the lit triangle itself; far cap: the same at infinity, reversed (skipped for a
  // directional light, where it would collapse to a point)
  emit(vec4(t0, 1.0));
  emit(vec4(t1, 1.0));
  emit(vec4(t2, 1.0));
  EndPrimitive();
  if (u_light.w != 0.0) {
    emit(at_infinity(t0));
    emit(at_infinity(t2));
    emit(at_infinity(t1));
    EndPrimitive();
  }
}
