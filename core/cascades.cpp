#include "core/cascades.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

std::vector<float> practical_splits(float near_plane, float far_plane, int count, float lambda) {
  std::vector<float> splits(static_cast<std::size_t>(count) + 1);
  for (int i = 0; i <= count; ++i) {
    const double t = static_cast<double>(i) / count;
    const double logarithmic = near_plane * std::pow(static_cast<double>(far_plane) / near_plane, t);
    const double uniform = near_plane + (static_cast<double>(far_plane) - near_plane) * t;
    splits[static_cast<std::size_t>(i)] = static_cast<float>(lambda * logarithmic + (1.0 - lambda) * uniform);
  }
  splits.front() = near_plane;  // exact ends, whatever pow rounds to
  splits.back() = far_plane;
  return splits;
}

LightView fit_cascade_sphere(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene) {
  // 1. The slice's bounding sphere: centre the corners' mean, radius the farthest corner. The corners
  // move rigidly with the camera, so the radius is the same wherever it looks.
  glm::dvec3 centre(0.0);
  for (const auto& c : slice) centre += glm::dvec3(c);
  centre /= 8.0;
  double radius = 0.0;
  for (const auto& c : slice) radius = std::max(radius, glm::length(glm::dvec3(c) - centre));
  radius = std::max(radius, 1e-6);
  // 2. The light's axes; the centre in the light's image plane, snapped down to whole texels.
  const glm::dmat3 basis(orthonormal_basis(glm::normalize(to_light)));
  // Snapping moves the box by up to one texel, so it is one texel wider than the sphere on every side:
  // map_size texels of 2 r / (map_size - 2) each.
  const double texel = 2.0 * radius / (map_size - 2);
  const double half_size = 0.5 * texel * map_size;
  const double x = std::floor(glm::dot(centre, basis[0]) / texel) * texel;
  const double y = std::floor(glm::dot(centre, basis[1]) / texel) * texel;
  // 3. Depth: the scene's extent along the light, around the scene's centre (the same for every cascade
  // and every frame, so a constant bias means the same everywhere).
  const glm::dvec3 scene_centre(scene.empty() ? glm::vec3(0.0f) : scene.center());
  const double z = glm::dot(scene_centre, basis[2]);
  double half_depth = 0.0;
  if (!scene.empty())
    for (int i = 0; i < 8; ++i) half_depth = std::max(half_depth,
    std::abs(glm::dot(glm::dvec3(scene.corner(i)) - scene_centre, basis[2])));
  half_depth = std::max(half_depth, 1e-6);
  const glm::dvec3 origin = basis[0] * x + basis[1] * y + basis[2] * z;
  const glm::dmat3 rows = glm::transpose(basis);
  glm::dmat4 view(rows);
  view[3] = glm::dvec4(-(rows * origin), 1.0);
  LightView lv;
  lv.view = glm::mat4(view);
  lv.projection = glm::mat4(glm::ortho(-half_size, half_size, -half_size, half_size, -half_depth, half_depth));
  lv.image_x = glm::vec3(basis[0]);
  lv.image_y = glm::vec3(basis[1]);
  lv.world_size = glm::vec2(static_cast<float>(2.0 * half_size));
  return lv;
}

FrustumCorners frustum_slice(const glm::mat4& camera_view, const glm::mat4& camera_projection, float near_depth,
                             float far_depth) {
  // From the camera's axes and the projection's scale factors, in double: inverting the whole
  // view-projection in float loses about 1e-4 of the far corners with a near plane 1000 times closer,
  // enough to change a cascade's radius when the camera merely turns.
  const glm::dmat4 to_world = glm::inverse(glm::dmat4(camera_view));
  const glm::dvec3 right(to_world[0]), up(to_world[1]), back(to_world[2]), eye(to_world[3]);
  const double sx = 1.0 / camera_projection[0][0], sy = 1.0 / camera_projection[1][1];  // tan of the half-angles
  FrustumCorners corners;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 ray = right * ((i & 1 ? 1.0 : -1.0) * sx) + up * ((i & 2 ? 1.0 : -1.0) * sy) - back;
    corners[static_cast<std::size_t>(i)] = glm::vec3(eye + ray * static_cast<double>(near_depth));
    corners[static_cast<std::size_t>(i) + 4] = glm::vec3(eye + ray * static_cast<double>(far_depth));
  }
  return corners;
}

int cascade_map_size(int budget, int count) {
  return std::max(4, static_cast<int>(std::floor(budget / std::sqrt(static_cast<double>(std::max(count, 1))))));
}

int CascadeFrame::cascade_of(const glm::vec3& world) const {
  const float depth = -(camera_view * glm::vec4(world, 1.0f)).z;
  for (int i = 0; i < count; ++i)
    if (depth <= splits[static_cast<std::size_t>(i) + 1]) return i;
  return -1;
}

CascadeFrame compute_cascades(const glm::mat4& camera_view, const glm::mat4& camera_projection, const glm::vec3& to_light,
                              const Bounds& scene, int count, float lambda, int budget, const CascadeSplitFn& splits,
                              const CascadeFitFn& fit) {
  if (count < 1 || count > kMaxCascades) throw std::invalid_argument("cascade count out of range");
  CascadeFrame f;
  f.count = count;
  f.map_size = cascade_map_size(budget, count);
  f.camera_view = camera_view;
  // The camera's own range. Not clamped to the scene: a clamp would move the splits (and so every
  // cascade's size) whenever the camera turns or moves, and the shadows would shimmer.
  f.near_depth = camera_projection[3][2] / (camera_projection[2][2] - 1.0f);
  f.far_depth = camera_projection[3][2] / (camera_projection[2][2] + 1.0f);
  f.splits = splits ? splits(f.near_depth, f.far_depth, count, lambda) : practical_splits(f.near_depth, f.far_depth, count, lambda);
  if (f.splits.size() != static_cast<std::size_t>(count) + 1)
    throw std::runtime_error("the cascade split function returned " + std::to_string(f.splits.size()) + " distances for " +
                             std::to_string(count) + " cascades (needs count + 1)");
  for (int i = 0; i < count; ++i) {
    const FrustumCorners slice = frustum_slice(camera_view, camera_projection, f.splits[static_cast<std::size_t>(i)],
                                               f.splits[static_cast<std::size_t>(i) + 1]);
    f.views.push_back(fit ? fit(slice, to_light, f.map_size, scene) : fit_cascade_sphere(slice, to_light, f.map_size,
    scene));
  }
  return f;
}

namespace param {

const IntParam csm_count{{"csm.count", "Cascades", ParamKind::Int, 4.0, 1.0, static_cast<double>(kMaxCascades),
    "How many slices the camera's view range is split into, each with a map of its own. The cascades share "
    "the texels of one shadow.map_size map (each floor(size / sqrt(count)) per side), so more cascades are "
    "sharper near the camera at the same memory.", {}, kInvalidatesShadowMap | kInvalidatesTargets}};
const FloatParam csm_lambda{{"csm.lambda", "Split blend (lambda)", ParamKind::Float, 0.75, 0.0, 1.0,
    "Where the splits go: 0 uniform (equal depth per cascade: the near cascade wastes its texels far away), "
    "1 logarithmic (equal ratio far / near: ideal texel density, but tiny near cascades), between: the "
    "practical blend lambda log + (1 - lambda) uniform.", {}, kInvalidatesShadowMap}};
const FloatParam csm_blend{{"csm.blend", "Blend band", ParamKind::Float, 0.0, 0.0, 0.5,
    "Share of each cascade's depth range, at its far end, over which its visibility fades into the next "
    "cascade's: hides the seam where the texel size jumps. 0: a hard switch.", {}}};
const BoolParam csm_show_cascades{{"csm.show_cascades", "Colour the cascades", ParamKind::Bool, 0.0, 0.0, 1.0,
    "Tints each pixel by the cascade it is shaded from (red, green, blue, yellow, ...): where the splits fall.", {}}};

}  // namespace param

std::vector<ParamSpec> csm_param_specs() {
  return specs_of(param::csm_count, param::csm_lambda, param::csm_blend, param::csm_show_cascades);
}

}  // namespace shadowlab
