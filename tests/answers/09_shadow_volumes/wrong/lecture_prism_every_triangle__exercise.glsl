// wrong: the lecture's alternative (a prism per triangle: near cap, far cap, three sides), for every triangle, turned inside out when it faces away; correct volumes, every edge of the mesh extruded twice
// expect: other-method
// fails: silhouettes.side_triangles_ratio_to_solution
// The edge a -> b swept to infinity, as the strip a, a at infinity, b, b at infinity.
void prism_side(vec3 a, vec3 b) {
  emit(vec4(a, 1.0));
  emit(at_infinity(a));
  emit(vec4(b, 1.0));
  emit(at_infinity(b));
  EndPrimitive();
}

// A prism from triangle (a, b, c), counter-clockwise seen from the light: every face outward.
void prism(vec3 a, vec3 b, vec3 c) {
  prism_side(a, b);
  prism_side(b, c);
  prism_side(c, a);
  if (!u_caps) return;
  emit(vec4(a, 1.0));
  emit(vec4(b, 1.0));
  emit(vec4(c, 1.0));
  EndPrimitive();
  if (directional_light()) return;
  emit(at_infinity(a));
  emit(at_infinity(c));
  emit(at_infinity(b));
  EndPrimitive();
}

void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  if (faces_light(t0, t1, t2))
    prism(t0, t1, t2);
  else
    prism(t0, t2, t1);  // facing away: the same prism, its order flipped so it faces the light
}
