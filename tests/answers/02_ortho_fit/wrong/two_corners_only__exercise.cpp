// wrong: half-lengths from the min and max corners only ('the extreme corners'), not all 8: other corners stick out for most directions
// expect: skipped-half
// fails: *.corners_outside
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
  for (const glm::vec3& v : {bounds.min, bounds.max}) {
    const glm::vec3 d = v - C;
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
  out.image_x = X;
  out.image_y = Y;
  out.world_size = glm::vec2(2.0f * hx, 2.0f * hy);
  return out;
}

}  // namespace shadowlab
