// wrong: near is the distance to the nearest corner (far the farthest corner's, rightly): a perspective near plane cuts across the axis, so a caster off the axis nearer in depth is clipped
// expect: partly-right
// fails: probe.near_clips
#include "labs/15_two_lights/flashlight_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView flashlight_view_exercise(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds) {
  const glm::vec3 p(node_to_world[3]);
  const glm::vec3 dir = -glm::normalize(glm::vec3(node_to_world[2]));
  float nearest = 1e30f, farthest = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const float distance = glm::length(bounds.corner(i) - p);
    nearest = std::min(nearest, distance);
    farthest = std::max(farthest, distance);
  }
  const float far_plane = farthest * 1.001f;
  const float near_plane = std::max(nearest * 0.999f, far_plane / kMaxFarOverNear);
  LightView v;
  v.view = glm::inverse(node_to_world);
  v.projection = glm::perspective(glm::radians(2.0f * cone_deg), 1.0f, near_plane, far_plane);
  return v;
}

}  // namespace shadowlab
