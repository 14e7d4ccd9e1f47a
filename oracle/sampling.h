// Deterministic stratified sampling shared by the ray-cast truths (soft_truth.cpp, ao_truth.cpp): the same
// inputs give the same truth, run after run and thread count after thread count.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace shadowlab {

// A well-mixed 32-bit integer hash (Wellons' "lowbias32") to [0, 1): the jitter of a sample in its cell.
inline float hash01(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return static_cast<float>(x >> 8) * (1.0f / 16777216.0f);
}

// The per-pixel seed of pixel index i.
inline std::uint32_t pixel_seed(std::size_t i) { return static_cast<std::uint32_t>(i) * 2654435761U; }

// Sample (sx, sy) of a k x k grid over the unit square, jittered within its cell by the pixel's seed.
inline glm::vec2 jittered_cell(std::uint32_t seed, int sx, int sy, int k) {
  const auto s = static_cast<std::uint32_t>(sy * k + sx);
  return {(static_cast<float>(sx) + hash01(seed ^ (2 * s + 1) * 0x9e3779b9U)) / static_cast<float>(k),
          (static_cast<float>(sy) + hash01(seed ^ (2 * s + 2) * 0x85ebca6bU)) / static_cast<float>(k)};
}

// Two unit vectors perpendicular to unit d and to each other.
inline void orthonormal_pair(const glm::vec3& d, glm::vec3& e1, glm::vec3& e2) {
  const glm::vec3 a = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  e1 = glm::normalize(glm::cross(a, d));
  e2 = glm::cross(d, e1);
}

}  // namespace shadowlab
