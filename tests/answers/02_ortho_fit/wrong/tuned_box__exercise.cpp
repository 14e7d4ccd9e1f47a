// wrong: fitted centre and axes, but a hand-tuned half-length of 12 that covers the default scene
// expect: tuned-to-scene
// fails: *.loose_directions *.corners_outside
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
  const float hx = 12.0f, hy = 12.0f, hz = 12.0f;  // big enough for the lab's scene
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
