// Error metrics of a rendered visibility image against the oracle's truth, and the diff image.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracle/oracle.h"
#include "oracle/soft_truth.h"

namespace shadowlab {

struct Metrics {
  // Over interior pixels (the edge band excluded); rendered visibility < 0.5 counts as shadowed.
  double acne_rate = 0.0;  // truly lit but rendered shadowed / truly lit
  double leak_rate = 0.0;  // truly shadowed but rendered lit / truly shadowed
  // The same over all valid pixels, edges included.
  double acne_rate_all = 0.0;
  double leak_rate_all = 0.0;
  // For soft techniques: mean |visibility - truth| over interior pixels and over the edge band, and
  // the bleeding rate: interior truly shadowed pixels rendered with visibility > 0.1.
  double mae_interior = 0.0;
  double mae_edge = 0.0;
  double bleeding_rate = 0.0;
  // The continuous errors of interior pixels, for answers that are partly wrong: the mean darkening of
  // truly lit pixels, mean(1 - visibility) (equal to acne_rate when visibility is 0 or 1), and the mean
  // light in truly shadowed ones, mean(visibility) (equal to leak_rate then). A lit surface drawn at
  // 0.875 everywhere has no acne at all but a lit_error of 0.125.
  double lit_error = 0.0;
  double shadow_error = 0.0;
  std::uint64_t valid_pixels = 0;
  std::uint64_t interior_lit = 0;
  std::uint64_t interior_shadowed = 0;
  std::uint64_t edge_pixels = 0;
  // Against a light with a size (add_soft_metrics, from compare_soft below; `soft` false and the rest 0
  // for a hard light): the mean |visibility - fraction| over the penumbra (the valid pixels that see
  // part of the light, 0 < fraction < 1), and over every valid pixel, with its two sides (too dark, too
  // light).
  bool soft = false;
  double penumbra_error = 0.0;
  double soft_mean_error = 0.0;
  double soft_too_dark = 0.0;
  double soft_too_light = 0.0;
  std::uint64_t penumbra_pixels = 0;
};

// visibility: one value per pixel in [0, 1], same layout as the truth.
// Only valid pixels count. The lit/shadowed decisions clamp values to [0, 1]; the mean errors (mae_*,
// lit_error, shadow_error) take them as they are, so out-of-range visibility is an error too. A NaN counts
// as the wrong answer (0 where the truth is lit, 1 where it is shadowed). Rates with a zero denominator are 0. Throws
// std::invalid_argument when the sizes do not match. compare() and diff_image() agree pixel by pixel.
Metrics compare(const Truth& truth, const std::vector<float>& visibility);

// The hard truth graded against a light with a size: `lit` becomes the soft truth's fraction >= 0.5 and
// only pixels that see all of the light or none of it (fraction exactly 1 or 0) stay interior, so the
// interior rates and errors grade the fully lit region and the umbra; the penumbra joins the edge band.
// `valid` keeps the pixels valid in both. Throws std::invalid_argument when the sizes differ.
Truth soften(const Truth& hard, const SoftTruth& soft);
// Sets m.soft and the soft figures of `visibility` against the soft truth (compare_soft's).
void add_soft_metrics(Metrics& m, const SoftTruth& soft, const std::vector<float>& visibility);

// The soft figures appear only when m.soft is set.
nlohmann::json to_json(const Metrics& m);

// RGBA8, row 0 at the top (ready for PNG): agreeing pixels in grey (lit light, shadowed dark), acne in
// red, leak in cyan-blue, the edge band tinted yellow, invalid pixels black.
// Edge-band pixels take the same colour blended 50% toward kDiffEdgeTint, rounding halves up
// ((c + tint + 1) / 2). Alpha is 255 everywhere.
std::vector<std::uint8_t> diff_image(const Truth& truth, const std::vector<float>& visibility);

// The diff image's colours (RGB).
using DiffColor = std::array<std::uint8_t, 3>;
inline constexpr DiffColor kDiffInvalid{0, 0, 0};
inline constexpr DiffColor kDiffLit{200, 200, 200};
inline constexpr DiffColor kDiffShadowed{70, 70, 70};
inline constexpr DiffColor kDiffAcne{255, 0, 0};
inline constexpr DiffColor kDiffLeak{0, 160, 255};
inline constexpr DiffColor kDiffEdgeTint{255, 220, 0};

// Against a light with a size (oracle/soft_truth.h) the truth is a fraction, and so is the error. Over
// valid pixels: the mean |visibility - visible fraction| (`mae`), split into what is drawn too dark
// (mean max(0, fraction - visibility)) and too light (mean max(0, visibility - fraction)), so mae =
// too_dark + too_light; and the mean over the penumbra alone (0 < fraction < 1). Visibility is taken as
// it is (outside [0, 1] is an error too); a NaN counts as the farther of 0 and 1. For a light of size 0
// mae is compare()'s error over all valid pixels (interior and edge band together; tested). Throws
// std::invalid_argument when the sizes do not match.
struct SoftMetrics {
  double mae = 0.0;
  double too_dark = 0.0;
  double too_light = 0.0;
  double mae_penumbra = 0.0;
  std::uint64_t valid_pixels = 0;
  std::uint64_t penumbra_pixels = 0;
};
SoftMetrics compare_soft(const SoftTruth& truth, const std::vector<float>& visibility);
nlohmann::json to_json(const SoftMetrics& m);

// RGBA8, row 0 at the top: the truth's fraction as a grey between kDiffShadowed and kDiffLit, turned
// toward kDiffAcne where drawn too dark and toward kDiffLeak where drawn too light, fully at an error of
// kSoftDiffFullError or more; invalid pixels black. Agrees with compare_soft pixel by pixel.
inline constexpr float kSoftDiffFullError = 0.25f;
std::vector<std::uint8_t> soft_diff_image(const SoftTruth& truth, const std::vector<float>& visibility);
// One valid pixel of it: the truth's visible fraction and the signed error (visibility - fraction, as
// soft_signed_error gives it). The legend (renderer/debug_annotations.h) samples the same function.
DiffColor soft_diff_colour(float fraction, double signed_error);

}  // namespace shadowlab
