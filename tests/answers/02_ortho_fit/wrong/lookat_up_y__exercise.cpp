// wrong: keeps the tutorial's lookAt with up = +Y (eye at C, looking along the light) and fits the half-lengths along its axes: NaN when the light points straight down
// expect: structure
// fails: *.non_finite_directions
#include "labs/02_ortho_fit/ortho_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light) {
  const glm::vec3 C = bounds.center();
  const glm::vec3 Z = glm::normalize(to_light);
  const glm::mat4 view = glm::lookAt(C, C - Z, glm::vec3(0.0f, 1.0f, 0.0f));  // eye at the centre, looking along the light
  const glm::vec3 X(view[0][0], view[1][0], view[2][0]);
  const glm::vec3 Y(view[0][1], view[1][1], view[2][1]);
  float hx = 0.0f, hy = 0.0f, hz = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 d = bounds.corner(i) - C;
    hx = std::max(hx, std::abs(glm::dot(d, X)));
    hy = std::max(hy, std::abs(glm::dot(d, Y)));
    hz = std::max(hz, std::abs(glm::dot(d, Z)));
  }
  LightView out;
  out.view = view;
  out.projection = glm::ortho(-hx, hx, -hy, hy, -hz, hz);
  out.image_x = X;
  out.image_y = Y;
  out.world_size = glm::vec2(2.0f * hx, 2.0f * hy);
  return out;
}

}  // namespace shadowlab
