// Light and camera maths, CPU only: the directional light, the light's view and projection, and the
// orbit camera. The fitted ortho projection is the course's task 2; the fixed box of the tutorials is
// here too, to compare it with.
#pragma once

#include <glm/glm.hpp>

#include "core/scene.h"

namespace shadowlab {

// Unit vector from the scene toward a directional light. Azimuth is measured in the ground plane from
// +X toward -Z (counter-clockwise seen from above); elevation from the ground plane up toward +Y.
glm::vec3 direction_from_angles(float azimuth_deg, float elevation_deg);

// A right-handed orthonormal basis whose third axis is `z`, stable for every unit `z` (including ±Y,
// where a lookAt with up = +Y degenerates). Columns: x, y, z.
glm::mat3 orthonormal_basis(const glm::vec3& z);

// Inside the scene's box the nearest geometry may be anywhere: a fitted perspective near plane is never
// less than far / this (fit_spot_light, point_light_views; lab 15's exercise uses the same floor).
inline constexpr float kMaxFarOverNear = 1000.0f;

struct LightView {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::vec3 image_x{1, 0, 0};  // world directions of the map's texel axes
  glm::vec3 image_y{0, 1, 0};
  glm::vec2 world_size{0.0f};  // width and height of the map's footprint in world units (ortho)

  glm::mat4 view_projection() const { return projection * view; }
};

// True when the box lies wholly outside the clip volume of view_proj (all eight corners beyond one of
// its six planes, tested in homogeneous clip space, so perspective and points behind the eye are
// handled): nothing in the box can be rasterised through that matrix. Conservative: a box that only
// straddles the volume's corner regions counts as inside. An empty box is outside.
bool box_outside_clip_volume(const Bounds& box, const glm::mat4& view_proj);

// The course's task 2: the light's view centred on the bounding box, axes X, Y orthogonal to the light
// direction Z, each half-length the largest |(V - C) . axis| over the box's 8 corners, so every corner
// maps into [-1, 1]^3 and the box touches the boundary on every axis.
LightView fit_light_ortho(const Bounds& bounds, const glm::vec3& to_light);

// The tutorials' fixed box: lookAt(direction, origin, up = +Y) with ortho(-10, 10, -10, 10, -10, 20).
// Degenerate for a light straight down, and wasteful or clipping for scenes of another size.
LightView fixed_tutorial_ortho(const glm::vec3& to_light);

// A spot light at `position` looking along `direction` (unit) with a cone of `cone_deg` half-angle: a
// perspective projection whose near and far planes are fitted to the scene's box (depth precision is
// spread between them). Near: the least depth along the axis of the box's 8 corners (a perspective near
// plane is a plane across the axis, so the distance to the box would clip a caster off the axis); when a
// corner is at or behind the light's plane (the light inside the box or beside it), far / 1000, never
// less. Far: the distance to the farthest corner, never less than a depth along the axis.
LightView fit_spot_light(const Bounds& bounds, const glm::vec3& position, const glm::vec3& direction, float cone_deg);

// The six 90-degree views of a point light, in GL's cube-map face order (+X, -X, +Y, -Y, +Z, -Z) with
// GL's face orientations, near and far fitted to the box as for the spot light, with the faces' axes:
// near is the largest of the light's per-axis gaps to the box (the least depth any face sees in it,
// down to 1/sqrt(3) of the distance to the box), never less than far / 1000 (its value inside the box).
struct CubeLightViews {
  glm::mat4 view[6];
  glm::mat4 projection{1.0f};
  float near_plane = 0.0f;
  float far_plane = 0.0f;
};
CubeLightViews point_light_views(const Bounds& bounds, const glm::vec3& position);

// Maps clip space [-1, 1] to texture space [0, 1] (the "bias matrix" of the course).
glm::mat4 clip_to_texture();

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float distance = 10.0f;
  float yaw_deg = 30.0f;    // around +Y
  float pitch_deg = 30.0f;  // above the ground plane
  float fov_y_deg = 45.0f;
  float near_plane = 0.1f;
  float far_plane = 100.0f;

  glm::vec3 eye() const;
  glm::mat4 view() const;
  glm::mat4 projection(float aspect) const;

  // Frames a bounding box: target at its centre, distance so the bounding sphere fits, near and far
  // planes as tight as the sphere allows (depth precision).
  static OrbitCamera framing(const Bounds& bounds, float yaw_deg = 30.0f, float pitch_deg = 30.0f);
  // A camera at `eye` looking at `target` (distinct points) with this vertical field of view; near and
  // far planes as tight as `bounds` allows (as framing's).
  static OrbitCamera looking(const glm::vec3& eye, const glm::vec3& target, float fov_y_deg, const Bounds& bounds);
};

}  // namespace shadowlab
