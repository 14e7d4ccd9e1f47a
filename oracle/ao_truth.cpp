#include "oracle/ao_truth.h"

#include <chrono>
#include <stdexcept>

#include "oracle/parallel_rows.h"
#include "oracle/sampling.h"
#include "oracle/soft_truth.h"

namespace shadowlab {

Scene ao_occluders(const Scene& scene) {
  Scene all = scene;
  for (auto& mesh : all.meshes) mesh.casts_shadow = true;
  return all;
}

AoTruth evaluate_ao(const Oracle& oracle, const GBuffer& g, float radius, int strata) {
  if (!(radius > 0.0f) || !std::isfinite(radius)) throw std::invalid_argument("evaluate_ao: radius must be finite and positive");
  if (strata < 1) throw std::invalid_argument("evaluate_ao: strata must be at least 1");
  const std::size_t count = checked_pixel_count(g, "evaluate_ao");
  const auto start = std::chrono::steady_clock::now();
  AoTruth t;
  t.width = g.width;
  t.height = g.height;
  t.samples = strata * strata;
  t.valid.assign(count, 0);
  t.open.assign(count, 0.0f);
  const auto w = static_cast<std::size_t>(g.width);
  t.rays = for_each_row_parallel(static_cast<std::size_t>(g.height), kTruthThreads, [&](std::size_t y) {
    std::uint64_t rays = 0;
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t i = y * w + x;
      const glm::vec3 p = g.position[i];
      const glm::vec3 n = g.normal[i];
      if (!g.covered[i] || !finite(p) || !finite(n) || !(glm::dot(n, n) > 0.0f)) continue;
      const glm::vec3 nz = glm::normalize(n);
      glm::vec3 e1, e2;
      orthonormal_pair(nz, e1, e2);
      const float eps = oracle.ray_epsilon(p);
      const glm::vec3 origin = p + nz * eps;
      const std::uint32_t seed = pixel_seed(i);
      int free = 0;
      for (int sy = 0; sy < strata; ++sy)
        for (int sx = 0; sx < strata; ++sx) {
          const glm::vec2 uv = jittered_cell(seed, sx, sy, strata);
          const glm::vec2 d = concentric_disk(uv.x, uv.y);  // Malley: lift the disk point to the hemisphere
          const float up = std::sqrt(std::max(0.0f, 1.0f - glm::dot(d, d)));
          const glm::vec3 dir = glm::normalize(d.x * e1 + d.y * e2 + up * nz);
          free += oracle.occluded(origin, dir, radius) ? 0 : 1;
        }
      rays += static_cast<std::uint64_t>(strata * strata);
      t.valid[i] = 1;
      t.open[i] = static_cast<float>(free) / static_cast<float>(strata * strata);
    }
    return rays;
  });
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

}  // namespace shadowlab
