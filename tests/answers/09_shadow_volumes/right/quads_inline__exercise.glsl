// right: writes every side quad inline with emit(), no helper function; caps as the lit triangle and its reversed copy at infinity
// expect: variant
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  vec3 v[3] = vec3[3](t0, t1, t2);
  bool silhouette[3] = bool[3](!faces_light(t0, n01, t1), !faces_light(t1, n12, t2), !faces_light(t2, n20, t0));
  for (int i = 0; i < 3; ++i) {
    if (!silhouette[i]) continue;
    vec3 a = v[i], b = v[(i + 1) % 3];
    emit(vec4(a, 1.0));
    emit(at_infinity(a));
    emit(vec4(b, 1.0));
    emit(at_infinity(b));
    EndPrimitive();
  }
  if (!u_caps) return;
  emit(vec4(t0, 1.0));
  emit(vec4(t1, 1.0));
  emit(vec4(t2, 1.0));
  EndPrimitive();
  if (directional_light()) return;
  emit(at_infinity(t0));
  emit(at_infinity(t2));
  emit(at_infinity(t1));
  EndPrimitive();
}
