// wrong: the view from the node and the cone's fov are right, but near and far are typed in (0.5 and 40, where the lab's scene fits): a smaller scene is cut by near, a larger one by far
// expect: tuned-to-scene
// fails: probe.near_clips probe.far_clips
#include "labs/15_two_lights/flashlight_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView flashlight_view_exercise(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds) {
  const glm::vec3 p(node_to_world[3]);
  const glm::vec3 dir = -glm::normalize(glm::vec3(node_to_world[2]));
  (void)bounds;
  LightView v;
  v.view = glm::inverse(node_to_world);
  v.projection = glm::perspective(glm::radians(2.0f * cone_deg), 1.0f, 0.5f, 40.0f);
  return v;
}

}  // namespace shadowlab
