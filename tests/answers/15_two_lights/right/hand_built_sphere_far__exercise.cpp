// right: the view's rows and the projection written out by hand (no glm::inverse, lookAt or perspective), near from the corners' depths in double, far from the box's bounding sphere along the axis
// expect: variant
#include "labs/15_two_lights/flashlight_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView flashlight_view_exercise(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds) {
  const glm::vec3 p(node_to_world[3]);
  const glm::vec3 dir = -glm::normalize(glm::vec3(node_to_world[2]));
  const glm::vec3 x = glm::normalize(glm::vec3(node_to_world[0]));
  const glm::vec3 z = -dir;
  const glm::vec3 y = glm::cross(z, x);
  double nearest = 1e300;
  for (int i = 0; i < 8; ++i) nearest = std::min(nearest, static_cast<double>(glm::dot(bounds.corner(i) - p, dir)));
  const glm::vec3 c = bounds.center();
  const float radius = 0.5f * glm::length(bounds.extent());
  const float f = (glm::dot(c - p, dir) + radius) * 1.001f;
  const float n = std::max(static_cast<float>(nearest * 0.999), f / kMaxFarOverNear);
  LightView v;
  v.view = glm::mat4(1.0f);
  for (int col = 0; col < 3; ++col) {
    v.view[col][0] = x[col];
    v.view[col][1] = y[col];
    v.view[col][2] = z[col];
  }
  v.view[3] = glm::vec4(-glm::dot(x, p), -glm::dot(y, p), -glm::dot(z, p), 1.0f);
  const float s = 1.0f / std::tan(glm::radians(cone_deg));
  v.projection = glm::mat4(0.0f);
  v.projection[0][0] = s;
  v.projection[1][1] = s;
  v.projection[2][2] = -(f + n) / (f - n);
  v.projection[2][3] = -1.0f;
  v.projection[3][2] = -2.0f * f * n / (f - n);
  return v;
}

}  // namespace shadowlab
