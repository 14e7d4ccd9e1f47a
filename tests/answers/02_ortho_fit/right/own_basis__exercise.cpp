// right: builds X, Y itself by crossing Z with the world axis least aligned with it (no orthonormal_basis), and scales with a matrix instead of glm::ortho
// expect: variant
#include "labs/02_ortho_fit/ortho_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light) {
  const glm::vec3 C = bounds.center();
  const glm::vec3 Z = glm::normalize(to_light);
  const glm::vec3 a = glm::abs(Z);
  const glm::vec3 helper = (a.x <= a.y && a.x <= a.z) ? glm::vec3(1, 0, 0)
                           : (a.y <= a.z)             ? glm::vec3(0, 1, 0)
                                                      : glm::vec3(0, 0, 1);
  const glm::vec3 X = glm::normalize(glm::cross(helper, Z));
  const glm::vec3 Y = glm::cross(Z, X);
  float hx = 0.0f, hy = 0.0f, hz = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 d = bounds.corner(i) - C;
    hx = std::max(hx, std::abs(glm::dot(d, X)));
    hy = std::max(hy, std::abs(glm::dot(d, Y)));
    hz = std::max(hz, std::abs(glm::dot(d, Z)));
  }
  glm::mat4 view(1.0f);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = X[c];
    view[c][1] = Y[c];
    view[c][2] = Z[c];
  }
  view[3] = glm::vec4(-glm::dot(X, C), -glm::dot(Y, C), -glm::dot(Z, C), 1.0f);
  // ortho(-h, h) per axis: x / hx, y / hy, and view z (toward the light) to depth -z / hz.
  glm::mat4 scale(1.0f);
  scale[0][0] = 1.0f / hx;
  scale[1][1] = 1.0f / hy;
  scale[2][2] = -1.0f / hz;
  LightView out;
  out.view = view;
  out.projection = scale;
  out.image_x = X;
  out.image_y = Y;
  out.world_size = glm::vec2(2.0f * hx, 2.0f * hy);
  return out;
}

}  // namespace shadowlab
