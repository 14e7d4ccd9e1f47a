// wrong: builds the view as glm::mat4(X, Y, Z, -C): glm takes columns, so the rotation is transposed and the translation is not rotated
// expect: structure
// fails: *.corners_outside *.inconsistent_axes
#include "labs/02_ortho_fit/ortho_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light) {
  const glm::vec3 C = bounds.center();
  const glm::vec3 Z = glm::normalize(to_light);
  const glm::mat3 basis = orthonormal_basis(Z);
  const glm::vec3 X = basis[0], Y = basis[1];
  float hx = 0.0f, hy = 0.0f, hz = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 d = bounds.corner(i) - C;
    hx = std::max(hx, std::abs(glm::dot(d, X)));
    hy = std::max(hy, std::abs(glm::dot(d, Y)));
    hz = std::max(hz, std::abs(glm::dot(d, Z)));
  }
  LightView out;
  out.view = glm::mat4(glm::vec4(X, 0.0f), glm::vec4(Y, 0.0f), glm::vec4(Z, 0.0f), glm::vec4(-C, 1.0f));
  out.projection = glm::ortho(-hx, hx, -hy, hy, -hz, hz);
  out.image_x = X;
  out.image_y = Y;
  out.world_size = glm::vec2(2.0f * hx, 2.0f * hy);
  return out;
}

}  // namespace shadowlab
