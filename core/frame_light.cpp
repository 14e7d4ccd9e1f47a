#include "core/frame_light.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

void FrameLight::update(const ParamSet& params, const Bounds& bounds, std::optional<LightType> pinned, const LightFit& fit,
                        const Placement& placement) {
  type = pinned ? *pinned : light_type(params);
  to_light = direction_from_angles(params.get(param::light_azimuth), params.get(param::light_elevation));
  size = params.get(param::light_size);
  if (type == LightType::Directional) {
    view = fit ? fit(bounds, to_light) : fit_light_ortho(bounds, to_light);
    return;
  }
  scene_position = {params.get(param::light_position_x), params.get(param::light_position_y),
                    params.get(param::light_position_z)};
  position = placement.to_local(scene_position);
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const glm::vec3 aim = centre - position;
  spot_direction = glm::length(aim) > 1e-6f ? glm::normalize(aim) : glm::vec3(0, -1, 0);
  to_light = -spot_direction;
  spot_cone_deg = params.get(param::light_cone_deg);
  if (type == LightType::Spot) {
    view = fit_spot_light(bounds, position, spot_direction, spot_cone_deg);
  } else {
    cube = point_light_views(bounds, position);
    view = LightView{};
    view.view = cube.view[0];
    view.projection = cube.projection;
  }
}

float FrameLight::soft_truth_size() const { return type == LightType::Directional ? glm::radians(size) : size; }

int FrameLight::matched_filter_radius(float distance, int map_size) const {
  if (type != LightType::Directional || !(size > 0.0f) || !(distance > 0.0f) || map_size <= 0) return -1;
  // The ortho box's texels: x and y may differ (a box fitted to the scene), the mean is matched.
  const glm::mat4& p = view.projection;
  if (p[0][0] == 0.0f || p[1][1] == 0.0f) return -1;
  const float texel = 0.5f * (2.0f / std::abs(p[0][0]) + 2.0f / std::abs(p[1][1])) / static_cast<float>(map_size);
  const float width = 2.0f * distance * std::tan(0.5f * glm::radians(size));
  const float radius = std::round((width / texel - 1.0f) * 0.5f);
  return static_cast<int>(std::clamp(radius, 0.0f, static_cast<float>(kMaxMatchedFilterRadius)));
}

glm::vec4 FrameLight::vector4() const {
  return type == LightType::Directional ? glm::vec4(to_light, 0.0f) : glm::vec4(position, 1.0f);
}

float FrameLight::texel_angle(int map_size) const {
  if (type == LightType::Spot) return 2.0f * std::tan(glm::radians(spot_cone_deg)) / static_cast<float>(map_size);
  if (type == LightType::Point) return 2.0f / static_cast<float>(map_size);  // a 90-degree face: 2 tan(45 deg) / size
  return 0.0f;
}

}  // namespace shadowlab
