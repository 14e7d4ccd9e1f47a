#include "oracle/ao_metrics.h"

#include <cmath>
#include <stdexcept>

namespace shadowlab {

namespace {

// 1 on covered pixels with a 4-neighbour off their tangent plane by more than the threshold, or a
// neighbour not covered; 1 on uncovered pixels too (the background is no interior).
std::vector<std::uint8_t> edges(const GBuffer& g, float radius) {
  const int w = g.width, h = g.height;
  std::vector<std::uint8_t> e(g.position.size(), 0);
  const float tau = kAoDiscontinuityShare * radius;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!g.covered[i]) {
        e[i] = 1;
        continue;
      }
      const int nx[4] = {x - 1, x + 1, x, x};
      const int ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4 && !e[i]; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
        const std::size_t j = static_cast<std::size_t>(ny[k]) * w + nx[k];
        e[i] = !g.covered[j] || std::abs(glm::dot(g.normal[i], g.position[j] - g.position[i])) > tau;
      }
    }
  return e;
}

// 1 where a marked pixel lies within `reach` pixels (a square): counts in a sliding window along the
// rows, then along the columns of the result.
std::vector<std::uint8_t> near_marked(const std::vector<std::uint8_t>& marked, int w, int h, int reach) {
  const auto spread = [reach](const std::vector<std::uint8_t>& in, int count, int length, std::size_t along,
                              std::size_t across) {
    std::vector<std::uint8_t> out(in.size(), 0);
    for (int line = 0; line < count; ++line) {
      const std::size_t base = static_cast<std::size_t>(line) * across;
      int in_window = 0;  // marked pixels within [k - reach, k + reach]
      for (int k = 0; k < reach && k < length; ++k) in_window += in[base + static_cast<std::size_t>(k) * along];
      for (int k = 0; k < length; ++k) {
        if (k + reach < length) in_window += in[base + static_cast<std::size_t>(k + reach) * along];
        if (k - reach - 1 >= 0) in_window -= in[base + static_cast<std::size_t>(k - reach - 1) * along];
        out[base + static_cast<std::size_t>(k) * along] = in_window > 0;
      }
    }
    return out;
  };
  const auto rows = spread(marked, h, w, 1, static_cast<std::size_t>(w));
  return spread(rows, w, h, static_cast<std::size_t>(w), 1);
}

}  // namespace

Bounds ao_view_bounds(const Scene& scene) {
  Bounds all;
  for (const Mesh& mesh : scene.meshes) {
    Bounds b;
    for (const glm::vec3& p : mesh.positions) b.extend(p);
    if (!b.empty() && b.max.y - b.min.y > 1e-3f) all.extend(b);
  }
  return all.empty() ? scene.bounds() : all;
}

std::vector<std::uint8_t> ao_interior(const GBuffer& g, float radius) {
  const std::size_t n = checked_pixel_count(g, "ao_interior");
  const auto e = edges(g, radius);
  const auto near = near_marked(e, g.width, g.height, kAoInteriorMargin);
  std::vector<std::uint8_t> interior(n, 0);
  for (std::size_t i = 0; i < n; ++i) interior[i] = g.covered[i] && !near[i];
  return interior;
}

AoInteriorError ao_interior_error(const GBuffer& g, const std::vector<float>& ao, const AoTruth& truth, float radius) {
  const std::size_t n = checked_pixel_count(g, "ao_interior_error");
  if (ao.size() != n || truth.open.size() != n || truth.valid.size() != n)
    throw std::invalid_argument("ao_interior_error: the AO image and the truth must have one value per pixel");
  const auto interior = ao_interior(g, radius);
  AoInteriorError r;
  double sum = 0.0, signed_sum = 0.0, open = 0.0, occluded = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!interior[i] || !truth.valid[i] || !std::isfinite(ao[i])) continue;
    const double err = static_cast<double>(ao[i]) - truth.open[i];
    sum += std::abs(err);
    signed_sum += err;
    ++r.interior_pixels;
    if (truth.open[i] >= kAoOpenTruth) {
      open += std::abs(err);
      ++r.open_pixels;
    } else if (truth.open[i] < kAoOccludedTruth) {
      occluded += std::abs(err);
      ++r.occluded_pixels;
    }
  }
  if (r.interior_pixels) {
    r.mean = sum / static_cast<double>(r.interior_pixels);
    r.mean_signed = signed_sum / static_cast<double>(r.interior_pixels);
  }
  if (r.open_pixels) r.open = open / static_cast<double>(r.open_pixels);
  if (r.occluded_pixels) r.occluded = occluded / static_cast<double>(r.occluded_pixels);
  return r;
}

}  // namespace shadowlab
