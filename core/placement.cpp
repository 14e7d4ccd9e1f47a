#include "core/placement.h"

#include "core/light.h"

namespace shadowlab {

// Moving the scene moves the light's box with it: the map is redrawn (and, with the local origin on,
// comes out the same).
namespace param {

const BoolParam scene_local_origin{{"scene.local_origin", "Local origin", ParamKind::Bool, 1.0, 0.0, 1.0,
    "Hand the GPU positions relative to the scene's placed origin (computed in double, rounded to float "
    "once) instead of world coordinates. Off, float32 holds the world coordinates: 1e6 units from the "
    "origin it keeps 1/16 of a unit, and the shadows break.", {}, kInvalidatesShadowMap}};
const DoubleParam scene_offset_x{{"scene.offset_x", "Scene offset x", ParamKind::Float, 0.0, -1e8, 1e8,
    "Moves the scene, its camera and its lights this far along x (world units): a georeferenced or "
    "open-world scene far from the origin.", {}, kInvalidatesShadowMap}};
const DoubleParam scene_offset_y{{"scene.offset_y", "Scene offset y", ParamKind::Float, 0.0, -1e8, 1e8,
    "As scene offset x, along y.", {}, kInvalidatesShadowMap}};
const DoubleParam scene_offset_z{{"scene.offset_z", "Scene offset z", ParamKind::Float, 0.0, -1e8, 1e8,
    "As scene offset x, along z.", {}, kInvalidatesShadowMap}};
const DoubleParam scene_scale{{"scene.scale", "Scene scale", ParamKind::Float, 1.0, 1e-5, 1e6,
    "Scales the scene, its camera and its lights about the scene's origin: millimetres or kilometres.", {},
    kInvalidatesShadowMap, true}};

}  // namespace param

std::vector<ParamSpec> placement_param_specs() {
  return specs_of(param::scene_local_origin, param::scene_offset_x, param::scene_offset_y, param::scene_offset_z,
      param::scene_scale);
}

Placement placement_from(const ParamSet& params) {
  Placement p;
  p.offset = {params.get(param::scene_offset_x), params.get(param::scene_offset_y), params.get(param::scene_offset_z)};
  p.scale = params.get(param::scene_scale);
  p.local_origin = params.get(param::scene_local_origin);
  return p;
}

Scene local_scene(const Scene& scene, const Placement& placement) {
  Scene out = scene;
  if (placement.is_identity()) return out;
  for (Mesh& mesh : out.meshes)
    for (glm::vec3& p : mesh.positions) p = placement.to_local(p);
  return out;
}

Bounds to_local(const Bounds& bounds, const Placement& placement) {
  if (bounds.empty() || placement.is_identity()) return bounds;
  Bounds out;
  out.extend(placement.to_local(bounds.min));
  out.extend(placement.to_local(bounds.max));
  return out;
}

OrbitCamera to_local(const OrbitCamera& camera, const Placement& placement) {
  if (placement.is_identity()) return camera;
  OrbitCamera out = camera;
  const auto s = static_cast<float>(placement.scale);
  out.target = placement.to_local(camera.target);
  out.distance = camera.distance * s;
  out.near_plane = camera.near_plane * s;
  out.far_plane = camera.far_plane * s;
  return out;
}

}  // namespace shadowlab
