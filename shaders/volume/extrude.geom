#version 330 core
// Stencil shadow volumes (lecture 9), built per triangle from GL_TRIANGLES_ADJACENCY: vertices 0, 2, 4
// are the triangle, 1, 3, 5 the far vertices of the neighbours across edges 0-2, 2-4 and 4-0. What a
// triangle emits (silhouette sides, caps) is decided in "lab/volume.glsl" (lab 9's exercise); the
// helpers below are what is not the lesson: a facing test that neighbours evaluate identically, the
// point at infinity, and emitting one vertex.
//
// Orientation: every face must be emitted counter-clockwise seen from outside its volume, so the
// stencil pass can count front faces +1 and back faces -1 (two-sided stencil).
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;  // room for three side quads (3 x 4) and two caps (2 x 3)

in vec3 v_world_position[];

uniform mat4 u_view_proj;  // the camera's, with the far plane at infinity
uniform vec4 u_light;      // w = 1: the position of a point or spot light; w = 0: direction toward the light
uniform bool u_caps;       // z-fail needs closed volumes; z-pass draws no caps
// Each vertex's world position (w = 0 a point at infinity). Only read when the grader captures the
// volumes' triangles (transform feedback) to tell sides from caps by where their corners are.
out vec4 v_world_corner;

bool directional_light() { return u_light.w == 0.0; }

vec3 toward_light(vec3 p) { return directional_light() ? u_light.xyz : u_light.xyz - p; }

// Does triangle (a, b, c), counter-clockwise from its front, face the light? A triangle and its
// neighbour's view of it must agree bit for bit, or an edge is emitted twice or not at all: start at the
// lexicographically smallest vertex so every rotation of the same triangle does the same arithmetic.
bool faces_light_from(vec3 a, vec3 b, vec3 c) {
  return dot(cross(b - a, c - a), toward_light((a + b + c) / 3.0)) > 0.0;
}
bool smaller(vec3 p, vec3 q) { return p.x < q.x || (p.x == q.x && (p.y < q.y || (p.y == q.y && p.z < q.z))); }
bool faces_light(vec3 a, vec3 b, vec3 c) {
  if (smaller(b, a) && smaller(b, c)) return faces_light_from(b, c, a);
  if (smaller(c, a) && smaller(c, b)) return faces_light_from(c, a, b);
  return faces_light_from(a, b, c);
}

// The point at infinity straight away from the light behind p: homogeneous w = 0 is a direction. The
// camera's far plane is at infinity and the z-fail stencil pass clamps depth (GL_DEPTH_CLAMP), so it is
// drawn at depth 1 instead of being clipped by rounding (z-pass counts nothing that far back).
vec4 at_infinity(vec3 p) { return vec4(-toward_light(p), 0.0); }

// One vertex of the current triangle strip, in world space (w = 1 a point, w = 0 a point at infinity).
// End each strip with EndPrimitive().
void emit(vec4 world) {
  gl_Position = u_view_proj * world;
  v_world_corner = world;
  EmitVertex();
}

#include "lab/volume.glsl"

void main() {
  v_world_corner = vec4(0.0);  // written here too: an exercise that emits nothing must still link with the capture
  emit_volume(v_world_position[0], v_world_position[1], v_world_position[2], v_world_position[3],
              v_world_position[4], v_world_position[5]);
}
