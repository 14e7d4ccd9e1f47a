// wrong: glm::lookAt from the node's position along its -Z with up = +Y, as the tutorials do: no basis (NaN) when the flashlight points straight down or up
// expect: structure
// fails: probe.non_finite
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
    const glm::vec3 to_corner = bounds.corner(i) - p;
    nearest = std::min(nearest, glm::dot(to_corner, dir));
    farthest = std::max(farthest, glm::length(to_corner));
  }
  const float far_plane = farthest * 1.001f;
  const float near_plane = std::max(nearest * 0.999f, far_plane / kMaxFarOverNear);
  LightView v;
  v.view = glm::lookAt(p, p + dir, glm::vec3(0.0f, 1.0f, 0.0f));
  v.projection = glm::perspective(glm::radians(2.0f * cone_deg), 1.0f, near_plane, far_plane);
  return v;
}

}  // namespace shadowlab
