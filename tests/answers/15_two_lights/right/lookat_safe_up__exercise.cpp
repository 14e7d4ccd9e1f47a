// right: glm::lookAt with an up vector that switches to +X when the light is nearly vertical, and the tighter far: the greatest depth along the axis of the corners, not the farthest corner's distance
// expect: variant
#include "labs/15_two_lights/flashlight_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView flashlight_view_exercise(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds) {
  const glm::vec3 p(node_to_world[3]);
  const glm::vec3 dir = -glm::normalize(glm::vec3(node_to_world[2]));
  const glm::vec3 up = std::abs(dir.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  float nearest = 1e30f, deepest = -1e30f;
  for (int i = 0; i < 8; ++i) {
    const float depth = glm::dot(bounds.corner(i) - p, dir);
    nearest = std::min(nearest, depth);
    deepest = std::max(deepest, depth);
  }
  const float far_plane = deepest * 1.001f;
  const float near_plane = std::max(nearest * 0.999f, far_plane / kMaxFarOverNear);
  LightView v;
  v.view = glm::lookAt(p, p + dir, up);
  v.projection = glm::perspective(2.0f * glm::radians(cone_deg), 1.0f, near_plane, far_plane);
  return v;
}

}  // namespace shadowlab
