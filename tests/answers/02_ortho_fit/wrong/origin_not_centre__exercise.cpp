// wrong: skips step 1: the view stays at the world origin, half-lengths are the largest |V . axis| about the origin
// expect: skipped-half
// fails: *.loose_directions
#include "labs/02_ortho_fit/ortho_fit.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {

LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light) {
  const glm::vec3 Z = glm::normalize(to_light);
  const glm::mat3 basis = orthonormal_basis(Z);
  const glm::vec3 X = basis[0], Y = basis[1];
  float hx = 0.0f, hy = 0.0f, hz = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 v = bounds.corner(i);
    hx = std::max(hx, std::abs(glm::dot(v, X)));
    hy = std::max(hy, std::abs(glm::dot(v, Y)));
    hz = std::max(hz, std::abs(glm::dot(v, Z)));
  }
  LightView out;
  glm::mat4 view(1.0f);
  for (int c = 0; c < 3; ++c) {
    view[c][0] = X[c];
    view[c][1] = Y[c];
    view[c][2] = Z[c];
  }
  out.view = view;
  out.projection = glm::ortho(-hx, hx, -hy, hy, -hz, hz);
  out.image_x = X;
  out.image_y = Y;
  out.world_size = glm::vec2(2.0f * hx, 2.0f * hy);
  return out;
}

}  // namespace shadowlab
