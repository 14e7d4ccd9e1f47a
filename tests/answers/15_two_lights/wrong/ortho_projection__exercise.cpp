// wrong: an orthographic box around the cone (as for the sun in lab 2) instead of a perspective projection: the flashlight's rays spread from a point
// expect: other-method
// fails: probe.not_perspective
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
  const float r = far_plane * std::tan(glm::radians(cone_deg));
  LightView v;
  v.view = glm::inverse(node_to_world);
  v.projection = glm::ortho(-r, r, -r, r, near_plane, far_plane);
  return v;
}

}  // namespace shadowlab
