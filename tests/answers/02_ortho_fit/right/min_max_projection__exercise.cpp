// right: min and max of each corner's projection (an ortho box from [lo, hi] per axis), view rows set through glm::transpose: the same box, since the bounds are symmetric about C
// expect: variant
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
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 d = bounds.corner(i) - C;
    const glm::vec3 p(glm::dot(d, X), glm::dot(d, Y), glm::dot(d, Z));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::mat3 rows_xyz = glm::transpose(glm::mat3(X, Y, Z));  // rows X, Y, Z
  glm::mat4 view(rows_xyz);
  view[3] = glm::vec4(-(rows_xyz * C), 1.0f);
  LightView out;
  out.view = view;
  // View z grows toward the light; ortho's near/far are distances along -z.
  out.projection = glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z);
  out.image_x = X;
  out.image_y = Y;
  out.world_size = glm::vec2(hi.x - lo.x, hi.y - lo.y);
  return out;
}

}  // namespace shadowlab
