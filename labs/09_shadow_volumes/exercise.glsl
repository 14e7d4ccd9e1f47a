// Lab 9 exercise: what one triangle contributes to its mesh's shadow volume. Edit this file; the lab
// reloads it when you save. It runs in the geometry shader shaders/volume/extrude.geom, once per
// triangle, drawn as GL_TRIANGLES_ADJACENCY:
//   t0, t1, t2: the triangle, counter-clockwise seen from its front;
//   n01, n12, n20: the far vertex of the neighbouring triangle across edge t0-t1, t1-t2 and t2-t0.
// Helpers from extrude.geom:
//   faces_light(a, b, c)  does triangle a, b, c (counter-clockwise from its front) face the light? Two
//                         triangles sharing an edge get consistent answers from it;
//   at_infinity(p)        the point at infinity straight away from the light behind p (w = 0);
//   emit(vec4 p)          one vertex of the current triangle strip (world space); EndPrimitive() ends it;
//   directional_light()   true for a directional light; u_caps: true when the stencil counting is z-fail.
// The output is a triangle strip of at most 18 vertices per call (max_vertices in extrude.geom).
// Every face you emit must be counter-clockwise seen from OUTSIDE the volume: the stencil pass counts
// front faces and back faces with opposite signs.
void emit_volume(vec3 t0, vec3 n01, vec3 t1, vec3 n12, vec3 t2, vec3 n20) {
  // TODO: nothing is emitted yet, so nothing is in shadow. Build the shadow volume:
  //   1. the sides: a quad from each silhouette edge out to infinity, each silhouette edge once;
  //   2. when u_caps is set (z-fail counting), close the volume with a near cap and a far cap.
  // Then run: shadowlab check --lab 9 --impl exercise   (add --out DIR for the pictures)
}
