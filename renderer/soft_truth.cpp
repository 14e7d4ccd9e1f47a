#include "renderer/soft_truth.h"

#include "renderer/parallel_rows.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace shadowlab {
namespace {

constexpr unsigned kMaxThreads = 2;  // as the hard truth: this machine's cores, and CI's

// A well-mixed 32-bit integer hash (Wellons' "lowbias32") to [0, 1): the jitter of a sample in its cell.
float hash01(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return static_cast<float>(x >> 8) * (1.0f / 16777216.0f);
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Two unit vectors perpendicular to unit d and to each other.
void basis(const glm::vec3& d, glm::vec3& e1, glm::vec3& e2) {
  const glm::vec3 a = std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  e1 = glm::normalize(glm::cross(a, d));
  e2 = glm::cross(d, e1);
}

}  // namespace

glm::vec2 concentric_disk(float u, float v) {
  const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f};
  constexpr float kQuarter = std::numbers::pi_v<float> / 4.0f;
  const bool wide = std::abs(a) > std::abs(b);
  const float r = wide ? a : b;
  const float phi = wide ? kQuarter * (b / a) : 2.0f * kQuarter - kQuarter * (a / b);
  return {r * std::cos(phi), r * std::sin(phi)};
}

SoftTruth evaluate_soft(const Oracle& oracle, const GBuffer& gbuffer, const OracleLight& light, float size,
                        int strata) {
  if (!(size >= 0.0f) || !std::isfinite(size)) throw std::invalid_argument("soft truth: the light's size must be finite and >= 0");
  if (!light.positional && !(size < std::numbers::pi_v<float>))
    throw std::invalid_argument("soft truth: a directional light's angular diameter must be below pi");
  if (strata < 1) throw std::invalid_argument("soft truth: strata must be >= 1");
  if (gbuffer.width < 0 || gbuffer.height < 0) throw std::invalid_argument("soft truth: negative G-buffer size");
  const auto width = static_cast<std::size_t>(gbuffer.width), height = static_cast<std::size_t>(gbuffer.height);
  const std::size_t count = width * height;
  if (gbuffer.position.size() != count || gbuffer.normal.size() != count || gbuffer.covered.size() != count)
    throw std::invalid_argument("soft truth: G-buffer arrays do not match its size");
  glm::vec3 to_light(0.0f), sun_e1(0.0f), sun_e2(0.0f);
  if (light.positional) {
    if (!finite(light.position)) throw std::invalid_argument("soft truth: light position is not finite");
  } else {
    const float len = glm::length(light.to_light);
    if (!(len > 0.0f) || !std::isfinite(len)) throw std::invalid_argument("soft truth: light direction is zero or not finite");
    to_light = light.to_light / len;
    basis(to_light, sun_e1, sun_e2);
  }
  const bool hard = size == 0.0f;
  const int k = hard ? 1 : strata;
  // The disk: at unit distance along the sun's direction (radius tan of half the angular diameter), or
  // around the positional light's centre.
  const float radius = light.positional ? size : std::tan(0.5f * size);

  SoftTruth out;
  out.width = gbuffer.width;
  out.height = gbuffer.height;
  out.samples = k * k;
  out.valid.assign(count, 0);
  out.visible.assign(count, 0.0f);
  const auto start = std::chrono::steady_clock::now();

  // One pixel: its visible fraction; returns the rays cast.
  auto pixel = [&](std::size_t i) -> std::uint64_t {
    if (!gbuffer.covered[i]) return 0;
    const glm::vec3 p = gbuffer.position[i];
    glm::vec3 n = gbuffer.normal[i];
    if (!finite(p) || !finite(n) || !(glm::length(n) > 0.0f)) return 0;
    n = glm::normalize(n);
    glm::vec3 l = to_light, e1 = sun_e1, e2 = sun_e2;
    if (light.positional) {
      const glm::vec3 d = light.position - p;
      const float dist = glm::length(d);
      if (!(dist > 0.0f) || !std::isfinite(dist)) return 0;
      l = d / dist;
      basis(l, e1, e2);  // the disk faces the point
    }
    if (!(glm::dot(n, l) > 0.0f)) return 0;
    out.valid[i] = 1;
    const float eps = oracle.ray_epsilon(p);
    const glm::vec3 origin = p + n * eps;
    // Whether the segment from the pixel to the light's point at disk offset (x, y) is free. The centre
    // (a light of size 0) is the hard truth's own ray, bit for bit; a point of the disk behind the
    // pixel's surface is hidden by the surface itself.
    auto reaches = [&](float x, float y) {
      if (!light.positional) {
        const glm::vec3 dir = hard ? l : glm::normalize(l + x * e1 + y * e2);
        if (!hard && !(glm::dot(n, dir) > 0.0f)) return false;
        return !oracle.occluded(origin, dir, std::numeric_limits<float>::infinity());
      }
      const glm::vec3 d = light.position + x * e1 + y * e2 - origin;
      const float dist = glm::length(d);
      if (!(dist > eps)) return true;  // that point of the light is within the offset
      if (!hard && !(glm::dot(n, d) > 0.0f)) return false;
      return !oracle.occluded(origin, d / dist, dist - eps);
    };
    if (hard) {
      out.visible[i] = reaches(0.0f, 0.0f) ? 1.0f : 0.0f;
      return 1;
    }
    int free = 0;
    const auto seed = static_cast<std::uint32_t>(i) * 2654435761U;
    for (int sy = 0; sy < k; ++sy)
      for (int sx = 0; sx < k; ++sx) {
        const auto s = static_cast<std::uint32_t>(sy * k + sx);
        const float u = (static_cast<float>(sx) + hash01(seed ^ (2 * s + 1) * 0x9e3779b9U)) / static_cast<float>(k);
        const float v = (static_cast<float>(sy) + hash01(seed ^ (2 * s + 2) * 0x85ebca6bU)) / static_cast<float>(k);
        const glm::vec2 q = radius * concentric_disk(u, v);
        free += reaches(q.x, q.y) ? 1 : 0;
      }
    out.visible[i] = static_cast<float>(free) / static_cast<float>(k * k);
    return static_cast<std::uint64_t>(k * k);
  };

  out.rays = for_each_row_parallel(height, kMaxThreads, [&](std::size_t y) {
    std::uint64_t rays = 0;
    for (std::size_t x = 0; x < width; ++x) rays += pixel(y * width + x);
    return rays;
  });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace shadowlab
