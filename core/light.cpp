#include "core/light.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

// A point light's six cube faces: square views of this field of view cover every direction once.
constexpr float kCubeFaceFovDeg = 90.0f;

glm::vec3 direction_from_angles(float azimuth_deg, float elevation_deg) {
  // cos(radians(90)) is -4.4e-8 in float, not 0: make "straight down" exactly straight down.
  if (elevation_deg >= 90.0f) return {0.0f, 1.0f, 0.0f};
  const float az = glm::radians(azimuth_deg), el = glm::radians(elevation_deg);
  return glm::normalize(glm::vec3(std::cos(el) * std::cos(az), std::sin(el), -std::cos(el) * std::sin(az)));
}

glm::mat3 orthonormal_basis(const glm::vec3& z) {
  // Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017): branch-free but for the sign,
  // exact for every unit vector, no up-vector to become parallel to z.
  const float sign = std::copysign(1.0f, z.z);
  const float a = -1.0f / (sign + z.z);
  const float b = z.x * z.y * a;
  const glm::vec3 x(1.0f + sign * z.x * z.x * a, sign * b, -sign * z.x);
  const glm::vec3 y(b, sign + z.y * z.y * a, -z.y);
  return glm::mat3(x, y, z);
}

LightView fit_light_ortho(const Bounds& scene_bounds, const glm::vec3& to_light) {
  // An empty scene has no box: fit a unit box at the origin so the matrices stay finite.
  Bounds bounds = scene_bounds;
  if (bounds.empty()) {
    bounds.extend(glm::vec3(-1.0f));
    bounds.extend(glm::vec3(1.0f));
  }
  // Computed in double: a scene 1e4 or 1e6 units from the origin loses the box's own size in float
  // rounding of C and (V - C); only the finished matrices are rounded to float.
  const glm::dvec3 lo(bounds.min), hi(bounds.max);
  // 1. Centre C of the bounding box: the centre of the light's view.
  const glm::dvec3 c = 0.5 * (lo + hi);
  // 2. Axes: Z along the light (the light looks down -Z, toward the scene), X and Y any orthonormal pair.
  const glm::dmat3 basis(orthonormal_basis(glm::normalize(to_light)));
  // 3. Half-lengths: the largest |(V - C) . axis| over the 8 corners.
  glm::dvec3 half(0.0);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 d = glm::dvec3(bounds.corner(i)) - c;
    for (int axis = 0; axis < 3; ++axis) half[axis] = std::max(half[axis], std::abs(glm::dot(d, basis[axis])));
  }
  // A flat scene has no extent along some axis: keep the matrix invertible with a tiny relative extent.
  const double floor_extent = std::max(1e-6 * glm::length(hi - lo), 1e-6 * std::max(1.0, glm::length(c)));
  half = glm::max(half, glm::dvec3(std::max(floor_extent, 1e-30)));
  // 4. View: rows are the axes, origin at C. Projection: each axis scaled by its half-length, so the box
  // maps onto [-1, 1]^3; the light side (+Z) is nearest (depth -1).
  const glm::dmat3 rows = glm::transpose(basis);
  glm::dmat4 view(rows);
  view[3] = glm::dvec4(-(rows * c), 1.0);
  const glm::dmat4 projection = glm::ortho(-half.x, half.x, -half.y, half.y, -half.z, half.z);
  LightView lv;
  lv.view = glm::mat4(view);
  lv.projection = glm::mat4(projection);
  lv.image_x = glm::vec3(basis[0]);
  lv.image_y = glm::vec3(basis[1]);
  lv.world_size = glm::vec2(2.0 * half.x, 2.0 * half.y);
  return lv;
}

LightView fixed_tutorial_ortho(const glm::vec3& to_light) {
  LightView lv;
  lv.view = glm::lookAt(to_light, glm::vec3(0.0f), glm::vec3(0, 1, 0));
  lv.projection = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, -10.0f, 20.0f);
  lv.image_x = glm::vec3(glm::row(lv.view, 0));
  lv.image_y = glm::vec3(glm::row(lv.view, 1));
  lv.world_size = glm::vec2(20.0f);
  return lv;
}

namespace {
// The distance from a point to the box's farthest corner. A distance is never less than the depth along
// any axis, so this far plane clips nothing, whichever way the light looks.
float farthest_corner(const Bounds& bounds, const glm::vec3& p) {
  float far_distance = 0.0f;
  for (int i = 0; i < 8; ++i) far_distance = std::max(far_distance, glm::distance(bounds.corner(i), p));
  return std::max(far_distance, 1e-6f);
}
}  // namespace

LightView fit_spot_light(const Bounds& bounds, const glm::vec3& position, const glm::vec3& direction, float cone_deg) {
  const glm::vec3 axis = glm::normalize(direction);
  // A perspective near plane is a plane across the axis, not a sphere around the light: a point r away
  // and theta off the axis lies at depth r cos(theta), nearer than r. So near is the least depth along
  // the axis over the box, which (depth being linear) a corner attains; the distance to the box is only
  // an upper bound and clips a caster off the axis. In double: the corners' offsets from a light far from
  // them keep their small differences.
  double nearest_depth = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 8; ++i)
    nearest_depth = std::min(nearest_depth, glm::dot(glm::dvec3(bounds.corner(i)) - glm::dvec3(position), glm::dvec3(axis)));
  // Small margins so the box's nearest and farthest points are not clipped by rounding. A corner at or
  // behind the light's plane (the light inside the box, or low beside it): nothing can be assumed about
  // the nearest depth inside the cone, and only a small fraction of far is safe.
  const float far_plane = farthest_corner(bounds, position) * 1.001f;
  const float near_plane = std::max(static_cast<float>(nearest_depth) * 0.999f, far_plane / kMaxFarOverNear);
  const glm::mat3 basis = orthonormal_basis(-axis);  // the light looks down -Z
  LightView lv;
  lv.view = glm::mat4(glm::transpose(basis));
  lv.view[3] = glm::vec4(-(glm::transpose(basis) * position), 1.0f);
  lv.projection = glm::perspective(glm::radians(2.0f * cone_deg), 1.0f, near_plane, far_plane);
  lv.image_x = basis[0];
  lv.image_y = basis[1];
  lv.world_size = glm::vec2(0.0f);  // perspective: texels grow with distance
  return lv;
}

CubeLightViews point_light_views(const Bounds& bounds, const glm::vec3& position) {
  CubeLightViews cube;
  cube.far_plane = farthest_corner(bounds, position) * 1.001f;
  // The six faces are the world's axes, and a point lies in the face of its largest offset from the
  // light, at depth max(|dx|, |dy|, |dz|) along that face's axis: as little as 1/sqrt(3) of its distance.
  // The least such depth over the box is the largest of its per-axis gaps to the box (the box's
  // Chebyshev distance; 0 inside, where only a small fraction of far is safe). The Euclidean distance to
  // the box is only an upper bound, and clips a caster toward a face's corner.
  const glm::vec3 gap = glm::max(glm::max(bounds.min - position, position - bounds.max), glm::vec3(0.0f));
  const float nearest_depth = std::max(gap.x, std::max(gap.y, gap.z));
  cube.near_plane = std::max(nearest_depth * 0.999f, cube.far_plane / kMaxFarOverNear);
  cube.projection = glm::perspective(glm::radians(kCubeFaceFovDeg), 1.0f, cube.near_plane, cube.far_plane);
  // GL's cube-map faces: direction and up for +X, -X, +Y, -Y, +Z, -Z (the up vectors point down on the
  // side faces because cube maps are addressed with t growing downward).
  const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
  for (int f = 0; f < 6; ++f) cube.view[f] = glm::lookAt(position, position + dirs[f], ups[f]);
  return cube;
}

glm::mat4 clip_to_texture() {
  glm::mat4 m(0.5f);
  m[3] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
  return m;
}

glm::vec3 OrbitCamera::eye() const {
  const float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
  return target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw));
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), target, glm::vec3(0, 1, 0)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
  return glm::perspective(glm::radians(fov_y_deg), aspect, near_plane, far_plane);
}

OrbitCamera OrbitCamera::looking(const glm::vec3& eye, const glm::vec3& target, float fov_y_deg, const Bounds& bounds) {
  OrbitCamera cam;
  const glm::vec3 d = eye - target;
  cam.target = target;
  cam.distance = std::max(glm::length(d), 1e-6f);
  cam.yaw_deg = glm::degrees(std::atan2(d.x, d.z));
  cam.pitch_deg = glm::degrees(std::asin(std::clamp(d.y / cam.distance, -1.0f, 1.0f)));
  cam.fov_y_deg = fov_y_deg;
  if (bounds.empty()) return cam;
  const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-6f);
  const float to_centre = glm::length(eye - bounds.center());
  cam.far_plane = to_centre + radius;
  cam.near_plane = std::max(to_centre - radius, 1e-3f * cam.far_plane);
  return cam;
}

OrbitCamera OrbitCamera::framing(const Bounds& bounds, float yaw_deg, float pitch_deg) {
  OrbitCamera cam;
  cam.yaw_deg = yaw_deg;
  cam.pitch_deg = pitch_deg;
  if (bounds.empty()) return cam;
  cam.target = bounds.center();
  const float radius = std::max(0.5f * glm::length(bounds.extent()), 1e-6f);
  // Distance at which the bounding sphere fits the vertical field of view, with a little margin.
  // 0.8: the bounding sphere of a flat scene is far larger than what the view needs to show.
  cam.distance = 0.8f * radius / std::sin(glm::radians(0.5f * cam.fov_y_deg));
  cam.near_plane = std::max(cam.distance - radius, 1e-3f * cam.distance);
  cam.far_plane = cam.distance + radius;
  return cam;
}

bool box_outside_clip_volume(const Bounds& box, const glm::mat4& view_proj) {
  if (box.empty()) return true;
  glm::vec4 clip[8];
  for (int i = 0; i < 8; ++i) clip[i] = view_proj * glm::vec4(box.corner(i), 1.0f);
  // Plane k: axis k / 2, side +1 (x <= w) or -1 (x >= -w); a corner is outside when side * x > w.
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      bool all_outside = true;
      for (int i = 0; i < 8 && all_outside; ++i) all_outside = side * clip[i][axis] > clip[i].w;
      if (all_outside) return true;
    }
  return false;
}

}  // namespace shadowlab
