// wrong: extrudes the silhouettes a fixed distance ('far enough for this scene') instead of to infinity, and closes the volume with the extruded triangle: long shadows under a low sun stop short
// expect: tuned-to-scene
// fails: held_out_low_zfail.interior_agreement
// How far a volume reaches past its occluder, in world units: well past the objects of the lab's scene.
const float EXTRUDE_DISTANCE = 8.0;

// The point this far behind p, straight away from the light (at_infinity gives the direction).
vec4 extruded(vec3 p) { return vec4(p + EXTRUDE_DISTANCE * normalize(at_infinity(p).xyz), 1.0); }

// One side: the edge a -> b, in the lit triangle's order, swept away from the light.
void side(vec3 a, vec3 b) {
  emit(vec4(a, 1.0));
  emit(extruded(a));
  emit(vec4(b, 1.0));
  emit(extruded(b));
  EndPrimitive();
}

void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (!faces_light(t0, t1, t2)) return;
  if (!faces_light(t0, n01, t1)) side(t0, t1);
  if (!faces_light(t1, n12, t2)) side(t1, t2);
  if (!faces_light(t2, n20, t0)) side(t2, t0);
  if (!u_caps) return;
  // Near cap: the lit triangle, facing the light. Far cap: the triangle moved back, reversed, so it
  // faces away (for a directional light too: moved a finite distance it is not a point).
  emit(vec4(t0, 1.0));
  emit(vec4(t1, 1.0));
  emit(vec4(t2, 1.0));
  EndPrimitive();
  emit(extruded(t0));
  emit(extruded(t2));
  emit(extruded(t1));
  EndPrimitive();
}
