// wrong: floor(x / texel) without multiplying back by the texel
// expect: units
// fails: fit.slice_outside
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "labs/12_cascaded_shadow_maps/cascades_lab.h"

namespace shadowlab {

std::vector<float> cascade_splits_exercise(float near_plane, float far_plane, int count, float lambda) {
  std::vector<float> splits;
  for (int i = 0; i <= count; ++i) {
    const float t = static_cast<float>(i) / count;
    const float log_split = near_plane * std::pow(far_plane / near_plane, t);
    const float uniform_split = near_plane + (far_plane - near_plane) * t;
    splits.push_back(lambda * log_split + (1.0f - lambda) * uniform_split);
  }
  return splits;
}

LightView cascade_fit_exercise(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene) {
  glm::vec3 c(0.0f);
  for (const glm::vec3& p : slice) c += p;
  c /= 8.0f;
  float r = 0.0f;
  for (const glm::vec3& p : slice) r = std::max(r, glm::length(p - c));
  const glm::mat3 basis = orthonormal_basis(glm::normalize(to_light));
  const glm::vec3 X = basis[0], Y = basis[1], Z = basis[2];
  const float texel = 2.0f * r / (map_size - 2);
  const float h = 0.5f * texel * map_size;
  const float x = std::floor(glm::dot(c, X) / texel);
  const float y = std::floor(glm::dot(c, Y) / texel);
  const glm::vec3 b = scene.center();
  float hz = 0.0f;
  for (int i = 0; i < 8; ++i) hz = std::max(hz, std::abs(glm::dot(scene.corner(i) - b, Z)));
  const glm::vec3 o = X * x + Y * y + Z * glm::dot(b, Z);
  const glm::mat3 rows = glm::transpose(basis);
  LightView v;
  v.view = glm::mat4(rows);
  v.view[3] = glm::vec4(-(rows * o), 1.0f);
  v.projection = glm::ortho(-h, h, -h, h, -hz, hz);
  v.image_x = X;
  v.image_y = Y;
  v.world_size = glm::vec2(2.0f * h);
  return v;
}

}  // namespace shadowlab
