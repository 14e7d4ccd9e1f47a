#include "oracle/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace shadowlab {

namespace {

void check_sizes(const Truth& truth, const std::vector<float>& visibility) {
  if (truth.width < 0 || truth.height < 0) throw std::invalid_argument("metrics: negative truth size");
  const std::size_t count = static_cast<std::size_t>(truth.width) * static_cast<std::size_t>(truth.height);
  if (truth.valid.size() != count || truth.lit.size() != count || truth.interior.size() != count) {
    throw std::invalid_argument("metrics: truth arrays do not match its " + std::to_string(truth.width) + "x" +
                                std::to_string(truth.height) + " size");
  }
  if (visibility.size() != count) {
    throw std::invalid_argument("metrics: " + std::to_string(visibility.size()) + " visibility values for " +
                                std::to_string(count) + " pixels");
  }
}

// Rendered visibility in [0, 1]; NaN (a broken shader) counts as the wrong answer.
float sanitize(float v, bool truly_lit) {
  if (std::isnan(v)) return truly_lit ? 0.0f : 1.0f;
  return std::clamp(v, 0.0f, 1.0f);
}

void check_sizes(const SoftTruth& truth, const std::vector<float>& visibility) {
  if (truth.width < 0 || truth.height < 0) throw std::invalid_argument("metrics: negative soft truth size");
  const std::size_t count = static_cast<std::size_t>(truth.width) * static_cast<std::size_t>(truth.height);
  if (truth.valid.size() != count || truth.visible.size() != count)
    throw std::invalid_argument("metrics: soft truth arrays do not match its " + std::to_string(truth.width) + "x" +
                                std::to_string(truth.height) + " size");
  if (visibility.size() != count)
    throw std::invalid_argument("metrics: " + std::to_string(visibility.size()) + " visibility values for " +
                                std::to_string(count) + " pixels");
}

// The signed error against a visible fraction: visibility - fraction, a NaN as the farther of 0 and 1.
double soft_signed_error(float visibility, float fraction) {
  const double f = fraction;
  if (std::isnan(visibility)) return f >= 0.5 ? -f : 1.0 - f;
  return static_cast<double>(visibility) - f;
}

double ratio(std::uint64_t num, std::uint64_t den) {
  return den == 0 ? 0.0 : static_cast<double>(num) / static_cast<double>(den);
}

}  // namespace

Metrics compare(const Truth& truth, const std::vector<float>& visibility) {
  check_sizes(truth, visibility);
  std::uint64_t all_lit = 0, all_shadowed = 0, all_acne = 0, all_leak = 0;
  std::uint64_t interior_acne = 0, interior_leak = 0, interior_bleed = 0;
  double abs_interior = 0.0, abs_edge = 0.0, abs_lit = 0.0, abs_shadowed = 0.0;
  Metrics m;
  for (std::size_t i = 0; i < visibility.size(); ++i) {
    if (!truth.valid[i]) continue;
    ++m.valid_pixels;
    const bool truly_lit = truth.lit[i] != 0;
    const float v = sanitize(visibility[i], truly_lit);
    const bool rendered_lit = v >= 0.5f;
    // The continuous errors see values outside [0, 1] too (a shadow darker than the ambient term, a lit
    // surface brighter than lit): only NaN is replaced, by the wrong answer.
    const float raw = std::isnan(visibility[i]) ? (truly_lit ? 0.0f : 1.0f) : visibility[i];
    const double error = std::abs(static_cast<double>(raw) - (truly_lit ? 1.0 : 0.0));
    if (truly_lit) {
      ++all_lit;
      all_acne += !rendered_lit;
    } else {
      ++all_shadowed;
      all_leak += rendered_lit;
    }
    if (truth.interior[i]) {
      abs_interior += error;
      (truly_lit ? abs_lit : abs_shadowed) += error;
      if (truly_lit) {
        ++m.interior_lit;
        interior_acne += !rendered_lit;
      } else {
        ++m.interior_shadowed;
        interior_leak += rendered_lit;
        interior_bleed += v > 0.1f;
      }
    } else {
      ++m.edge_pixels;
      abs_edge += error;
    }
  }
  m.acne_rate = ratio(interior_acne, m.interior_lit);
  m.leak_rate = ratio(interior_leak, m.interior_shadowed);
  m.acne_rate_all = ratio(all_acne, all_lit);
  m.leak_rate_all = ratio(all_leak, all_shadowed);
  const std::uint64_t interior = m.interior_lit + m.interior_shadowed;
  m.mae_interior = interior == 0 ? 0.0 : abs_interior / static_cast<double>(interior);
  m.mae_edge = m.edge_pixels == 0 ? 0.0 : abs_edge / static_cast<double>(m.edge_pixels);
  m.bleeding_rate = ratio(interior_bleed, m.interior_shadowed);
  m.lit_error = m.interior_lit == 0 ? 0.0 : abs_lit / static_cast<double>(m.interior_lit);
  m.shadow_error = m.interior_shadowed == 0 ? 0.0 : abs_shadowed / static_cast<double>(m.interior_shadowed);
  return m;
}

namespace {
void check_soft_sizes(const SoftTruth& soft, std::size_t count) {
  if (static_cast<std::size_t>(soft.width) * static_cast<std::size_t>(soft.height) != count ||
      soft.valid.size() != count || soft.visible.size() != count)
    throw std::invalid_argument("metrics: the soft truth's " + std::to_string(soft.width) + "x" +
                                std::to_string(soft.height) + " arrays do not match " + std::to_string(count) + " pixels");
}
}  // namespace

Truth soften(const Truth& hard, const SoftTruth& soft) {
  const std::size_t count = hard.valid.size();
  check_soft_sizes(soft, count);
  if (hard.lit.size() != count || hard.interior.size() != count)
    throw std::invalid_argument("metrics: truth arrays do not match its size");
  Truth t = hard;
  for (std::size_t i = 0; i < count; ++i) {
    t.valid[i] = hard.valid[i] && soft.valid[i];
    const float f = soft.visible[i];
    t.lit[i] = t.valid[i] && f >= 0.5f;
    t.interior[i] = t.valid[i] && hard.interior[i] && (f == 0.0f || f == 1.0f);
  }
  t.seconds += soft.seconds;
  t.rays += soft.rays;
  return t;
}

void add_soft_metrics(Metrics& m, const SoftTruth& soft, const std::vector<float>& visibility) {
  const SoftMetrics s = compare_soft(soft, visibility);
  m.soft = true;
  m.penumbra_pixels = s.penumbra_pixels;
  m.penumbra_error = s.mae_penumbra;
  m.soft_too_dark = s.too_dark;
  m.soft_too_light = s.too_light;
  m.soft_mean_error = s.mae;
}

nlohmann::json to_json(const Metrics& m) {
  nlohmann::json j{
      {"acne_rate", m.acne_rate},
      {"leak_rate", m.leak_rate},
      {"acne_rate_all", m.acne_rate_all},
      {"leak_rate_all", m.leak_rate_all},
      {"mae_interior", m.mae_interior},
      {"mae_edge", m.mae_edge},
      {"bleeding_rate", m.bleeding_rate},
      {"lit_error", m.lit_error},
      {"shadow_error", m.shadow_error},
      {"valid_pixels", m.valid_pixels},
      {"interior_lit", m.interior_lit},
      {"interior_shadowed", m.interior_shadowed},
      {"edge_pixels", m.edge_pixels},
  };
  if (m.soft) {
    j["penumbra_error"] = m.penumbra_error;
    j["soft_too_dark"] = m.soft_too_dark;
    j["soft_too_light"] = m.soft_too_light;
    j["soft_mean_error"] = m.soft_mean_error;
    j["penumbra_pixels"] = m.penumbra_pixels;
  }
  return j;
}

std::vector<std::uint8_t> diff_image(const Truth& truth, const std::vector<float>& visibility) {
  check_sizes(truth, visibility);
  const std::size_t width = static_cast<std::size_t>(truth.width);
  const std::size_t height = static_cast<std::size_t>(truth.height);
  std::vector<std::uint8_t> image(width * height * 4, 0);
  for (std::size_t y = 0; y < height; ++y) {
    // The truth's row 0 is the bottom; the image's row 0 is the top.
    std::uint8_t* out_row = image.data() + (height - 1 - y) * width * 4;
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = y * width + x;
      std::uint8_t* px = out_row + x * 4;
      px[3] = 255;
      if (!truth.valid[i]) continue;  // black
      const bool truly_lit = truth.lit[i] != 0;
      const bool rendered_lit = sanitize(visibility[i], truly_lit) >= 0.5f;
      DiffColor c = truly_lit ? (rendered_lit ? kDiffLit : kDiffAcne) : (rendered_lit ? kDiffLeak : kDiffShadowed);
      if (!truth.interior[i]) {
        for (int k = 0; k < 3; ++k) c[k] = static_cast<std::uint8_t>((c[k] + kDiffEdgeTint[k] + 1) / 2);
      }
      px[0] = c[0];
      px[1] = c[1];
      px[2] = c[2];
    }
  }
  return image;
}

SoftMetrics compare_soft(const SoftTruth& truth, const std::vector<float>& visibility) {
  check_sizes(truth, visibility);
  SoftMetrics m;
  double dark = 0.0, light = 0.0, penumbra = 0.0;
  for (std::size_t i = 0; i < visibility.size(); ++i) {
    if (!truth.valid[i]) continue;
    ++m.valid_pixels;
    const double e = soft_signed_error(visibility[i], truth.visible[i]);
    (e < 0.0 ? dark : light) += std::abs(e);
    if (truth.visible[i] > 0.0f && truth.visible[i] < 1.0f) {
      ++m.penumbra_pixels;
      penumbra += std::abs(e);
    }
  }
  if (m.valid_pixels > 0) {
    const auto n = static_cast<double>(m.valid_pixels);
    m.too_dark = dark / n;
    m.too_light = light / n;
    m.mae = (dark + light) / n;
  }
  m.mae_penumbra = m.penumbra_pixels == 0 ? 0.0 : penumbra / static_cast<double>(m.penumbra_pixels);
  return m;
}

nlohmann::json to_json(const SoftMetrics& m) {
  return nlohmann::json{{"mae", m.mae},
                        {"too_dark", m.too_dark},
                        {"too_light", m.too_light},
                        {"mae_penumbra", m.mae_penumbra},
                        {"valid_pixels", m.valid_pixels},
                        {"penumbra_pixels", m.penumbra_pixels}};
}

DiffColor soft_diff_colour(float fraction, double signed_error) {
  const float f = std::clamp(fraction, 0.0f, 1.0f);
  const DiffColor& toward = signed_error < 0.0 ? kDiffAcne : kDiffLeak;
  const float t = static_cast<float>(std::min(1.0, std::abs(signed_error) / kSoftDiffFullError));
  DiffColor c{};
  for (std::size_t k = 0; k < 3; ++k) {
    const float grey = static_cast<float>(kDiffShadowed[k]) + f * static_cast<float>(kDiffLit[k] - kDiffShadowed[k]);
    c[k] = static_cast<std::uint8_t>(std::lround(grey + t * (static_cast<float>(toward[k]) - grey)));
  }
  return c;
}

std::vector<std::uint8_t> soft_diff_image(const SoftTruth& truth, const std::vector<float>& visibility) {
  check_sizes(truth, visibility);
  const std::size_t width = static_cast<std::size_t>(truth.width);
  const std::size_t height = static_cast<std::size_t>(truth.height);
  std::vector<std::uint8_t> image(width * height * 4, 0);
  for (std::size_t y = 0; y < height; ++y) {
    std::uint8_t* out_row = image.data() + (height - 1 - y) * width * 4;  // the truth's row 0 is the bottom
    for (std::size_t x = 0; x < width; ++x) {
      const std::size_t i = y * width + x;
      std::uint8_t* px = out_row + x * 4;
      px[3] = 255;
      if (!truth.valid[i]) continue;  // black
      const DiffColor c = soft_diff_colour(truth.visible[i], soft_signed_error(visibility[i], truth.visible[i]));
      for (int k = 0; k < 3; ++k) px[k] = c[static_cast<std::size_t>(k)];
    }
  }
  return image;
}

}  // namespace shadowlab
