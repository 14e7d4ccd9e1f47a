// centre and axes: the course's fit written directly
#include "labs/02_ortho_fit/ortho_fit.h"
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
namespace shadowlab {
LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light) {
  const glm::vec3 c = bounds.center();
  const glm::mat3 basis = orthonormal_basis(glm::normalize(to_light));
  const glm::vec3 x = basis[0], y = basis[1], z = basis[2];
  float hx = 0, hy = 0, hz = 0;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 d = bounds.corner(i) - c;
    hx = std::max(hx, std::abs(glm::dot(d, x)));
    hy = std::max(hy, std::abs(glm::dot(d, y)));
    hz = std::max(hz, std::abs(glm::dot(d, z)));
  }
  LightView v;
  glm::mat4 view(1.0f);
  for (int i = 0; i < 3; ++i) { view[i][0] = x[i]; view[i][1] = y[i]; view[i][2] = z[i]; }
  view[3][0] = -glm::dot(x, c); view[3][1] = -glm::dot(y, c); view[3][2] = -glm::dot(z, c);
  v.view = view;
  v.projection = glm::ortho(-hx, hx, -hy, hy, -hz, hz);
  v.image_x = x; v.image_y = y; v.world_size = {2 * hx, 2 * hy};
  return v;
}
}
