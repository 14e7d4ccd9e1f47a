// wrong: extrudes all three edges of every lit triangle, not the silhouette, to a finite point 1e5 units away in place of infinity (the shared sides cancel; the grader must still see them as sides)
// expect: structure
// fails: silhouettes.side_triangles_ratio_to_solution
// Far enough for any scene this lab draws, and finite: w = 1.
const float FAR_AWAY = 1.0e5;

vec4 far_behind(vec3 p) { return vec4(p + FAR_AWAY * normalize(at_infinity(p).xyz), 1.0); }

void side(vec3 a, vec3 b) {
  emit(vec4(a, 1.0));
  emit(far_behind(a));
  emit(vec4(b, 1.0));
  emit(far_behind(b));
  EndPrimitive();
}

void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  side(t0, t1);
  side(t1, t2);
  side(t2, t0);
  if (!u_caps) return;
  emit(vec4(t0, 1.0));
  emit(vec4(t1, 1.0));
  emit(vec4(t2, 1.0));
  EndPrimitive();
  emit(far_behind(t0));
  emit(far_behind(t2));
  emit(far_behind(t1));
  EndPrimitive();
}
