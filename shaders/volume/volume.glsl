// What one triangle contributes to its mesh's shadow volume (lab 9's solution).
//   t0, t1, t2: the triangle (counter-clockwise from its front);
//   n01, n12, n20: the far vertex of the neighbouring triangle across each edge. An open edge (the
//   lecture's "bad geometry") has the triangle's own opposite vertex there, so it always counts as a
//   silhouette and the volume stays closed on that side.
// Every face is emitted counter-clockwise seen from outside the volume (the stencil pass counts front
// faces and back faces with opposite signs).

// The side swept by edge a -> b (in the order the light-facing triangle runs it) out to infinity: a
// strip a, a at infinity, b, b at infinity keeps the triangle's orientation.
void emit_side(vec3 a, vec3 b) {
  emit(vec4(a, 1.0));
  emit(at_infinity(a));
  emit(vec4(b, 1.0));
  emit(at_infinity(b));
  EndPrimitive();
}

void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  // 1. Only triangles facing the light emit: every silhouette edge then comes from its lit side, once.
  if (!faces_light(t0, t1, t2)) return;
  // 2. A silhouette edge: the neighbour across it faces away. The neighbour across t0-t1 is t1, t0, n01
  // counter-clockwise from its own front; faces_light(t0, n01, t1) is the same triangle rotated.
  if (!faces_light(t0, n01, t1)) emit_side(t0, t1);
  if (!faces_light(t1, n12, t2)) emit_side(t1, t2);
  if (!faces_light(t2, n20, t0)) emit_side(t2, t0);
  // 3. Caps: z-fail counts the faces behind a surface, all the way to infinity, so every volume must be
  // closed: the lit triangle at the near end, facing the light (out of the volume) as it is ...
  if (!u_caps) return;
  emit(vec4(t0, 1.0));
  emit(vec4(t1, 1.0));
  emit(vec4(t2, 1.0));
  EndPrimitive();
  // ... and the same triangle at infinity at the far end, its order reversed so that it faces away from
  // the light (out of the volume again). A directional light sends every point to the same point at
  // infinity: that cap has no area and is left out.
  if (directional_light()) return;
  emit(at_infinity(t0));
  emit(at_infinity(t2));
  emit(at_infinity(t1));
  EndPrimitive();
}
