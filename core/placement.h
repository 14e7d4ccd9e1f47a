// Where the scene stands in the world, and the local origin the GPU works from (CPU only). A scene
// whose file puts it far from the origin keeps its own double origin (Scene::origin): the renderer adds
// it to the offset, so the same holds for a georeferenced model as for a moved one.
//
// The scene's vertices, the camera, the light positions and every grading buffer are in the scene's own
// frame (what a scene file or make_default_scene gives, what light.position_* and --camera mean). The
// placement moves all of it together into the world: world = offset + scale * p, in double. The same
// scene 1e6 units from the origin, or a thousand times smaller, is the same picture.
//
// float32 keeps 24 bits: at 1e6 its spacing is 0.0625 units, at 1e7 a whole unit, so a 12-unit scene
// there has no shape left and a view matrix that subtracts 1e6 from 1e6 in float cancels to noise. With
// the local origin on, the renderer hands the GPU (and every float computation: the light fits, lab 2's
// student fit, the camera's matrices) only offsets from a local origin, world - local_origin, computed in
// double and rounded once: small numbers whatever the offset. Off, the local origin is the world's
// origin and float32 holds the world coordinates themselves, as a naive renderer does: the teaching
// toggle "local origin" (scene.local_origin) shows the difference.
#pragma once

#include <glm/glm.hpp>

#include "core/params.h"
#include "core/scene.h"

namespace shadowlab {

struct OrbitCamera;

struct Placement {
  glm::dvec3 offset{0.0};  // where the scene's origin stands in the world
  double scale = 1.0;      // uniform, > 0
  bool local_origin = true;

  // The local origin in world coordinates: the scene's own origin as placed (the centre of the ortho
  // light box for scenes built around their origin, as the built-in ones and most models are); with the
  // toggle off, the world's origin.
  glm::dvec3 origin() const { return local_origin ? offset : glm::dvec3(0.0); }
  glm::dvec3 to_world(const glm::vec3& p) const { return offset + scale * glm::dvec3(p); }
  // Scene frame -> what the GPU gets (world - local origin, rounded to float once).
  glm::vec3 to_local(const glm::vec3& p) const { return glm::vec3(to_world(p) - origin()); }
  // What the GPU wrote (a G-buffer position) -> the scene's frame, for the oracle.
  glm::vec3 to_scene(const glm::vec3& local) const { return glm::vec3((glm::dvec3(local) + origin() - offset) / scale); }
  // True when to_local is the identity (no conversion needed, and none is made: bit for bit as before).
  bool is_identity() const { return scale == 1.0 && origin() == offset && offset == glm::dvec3(0.0); }
  bool operator==(const Placement&) const = default;
};

// The scene.* parameters (absent ones: the identity placement with the local origin on).
Placement placement_from(const ParamSet& params);
// The parameters' declarations: scene.offset_x/y/z, scene.scale, scene.local_origin.
std::vector<ParamSpec> placement_param_specs();
namespace param {
extern const BoolParam scene_local_origin;
extern const DoubleParam scene_offset_x;
extern const DoubleParam scene_offset_y;
extern const DoubleParam scene_offset_z;
extern const DoubleParam scene_scale;
}  // namespace param

// The scene as the GPU gets it: every position converted with to_local (normals unchanged: the scale is
// uniform and positive).
Scene local_scene(const Scene& scene, const Placement& placement);
Bounds to_local(const Bounds& bounds, const Placement& placement);
// The camera in the local frame: its target converted, distance and planes scaled.
OrbitCamera to_local(const OrbitCamera& camera, const Placement& placement);

}  // namespace shadowlab
