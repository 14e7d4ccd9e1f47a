// right: the view is the node's transform inverted (glm::inverse), and near and far keep a generous margin: 90 % of the least corner depth, 105 % of the farthest corner's distance
// expect: variant
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
    nearest = std::min(nearest, glm::dot(bounds.corner(i) - p, dir));
    farthest = std::max(farthest, glm::distance(bounds.corner(i), p));
  }
  const float far_plane = 1.05f * farthest;
  LightView v;
  v.view = glm::inverse(node_to_world);
  v.projection = glm::perspective(glm::radians(cone_deg * 2.0f), 1.0f, std::max(0.9f * nearest, far_plane / kMaxFarOverNear), far_plane);
  return v;
}

}  // namespace shadowlab
