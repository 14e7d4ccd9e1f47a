// wrong: image_x and image_y swapped (Y, X), so the map's texel axes do not match the matrix
// expect: part-ungraded
// fails: *.inconsistent_axes
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
  glm::mat4 view(1.0f);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = X[c];
    view[c][1] = Y[c];
    view[c][2] = Z[c];
  }
  view[3] = glm::vec4(-glm::dot(X, C), -glm::dot(Y, C), -glm::dot(Z, C), 1.0f);
  out.view = view;
  out.projection = glm::ortho(-hx, hx, -hy, hy, -hz, hz);
  out.image_x = Y;
  out.image_y = X;
  out.world_size = glm::vec2(2.0f * hy, 2.0f * hx);
  return out;
}

}  // namespace shadowlab
