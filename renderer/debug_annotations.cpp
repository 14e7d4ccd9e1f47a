#include "renderer/debug_annotations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "oracle/metrics.h"
#include "core/technique_params.h"

namespace shadowlab {

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

constexpr int kRampSteps = 32;

// A float as GLSL reads it (always with a point or an exponent).
std::string glsl_float(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(v));
  std::string s = text;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string glsl_vec3(const float (&c)[3]) {
  return "vec3(" + glsl_float(c[0]) + ", " + glsl_float(c[1]) + ", " + glsl_float(c[2]) + ")";
}

glm::vec3 vec3_of(const float (&c)[3]) { return {c[0], c[1], c[2]}; }

// What a tint blended at `opacity` over a mid grey looks like: the legend's stand-in for the picture.
glm::vec3 over_grey(const glm::vec3& tint, float opacity) { return glm::mix(glm::vec3(0.5f), tint, opacity); }  // enough that the bar shows the ramp's curve, not its segments

}  // namespace

glm::vec3 pcss_view_colour(float t) { return {t, t * t, 0.6f * (1.0f - t)}; }

float pcss_view_range(const ParamSet& params) {
  if (params.get(param::pcss_view) == "kernel width") return 2.0f * kPcssMaxRadiusTexels;
  return params.get(param::pcss_view_range);
}

std::optional<ColourLegend> pcss_view_legend(const ParamSet& params) {
  const std::string& view = params.get(param::pcss_view);
  if (view == "shadow") return std::nullopt;
  const float range = pcss_view_range(params);
  ColourLegend legend;
  for (int i = 0; i <= kRampSteps; ++i) legend.ramp.push_back(pcss_view_colour(static_cast<float>(i) / kRampSteps));
  legend.low = "0";
  if (view == "kernel width") {
    legend.title = "PCSS kernel width";
    legend.units = "the filter's diameter in shadow-map texels, log scale";
    legend.high = number(range) + " (the cap)";
    // Where the shader puts a width w: log2(1 + w) / log2(1 + range).
    for (float w : {4.0f, 16.0f})
      legend.ticks.emplace_back(std::log2(1.0f + w) / std::log2(1.0f + range), number(w));
    legend.swatches.emplace_back(glm::vec3(1.0f, 0.0f, 0.0f), "cut by the cap");
  } else {
    legend.title = "PCSS blocker distance";
    legend.units = "blockers' mean distance above the point, world units";
    legend.high = number(range) + " (pcss.view_range) or more";
    legend.ticks.emplace_back(0.5f, number(0.5 * range));
  }
  legend.swatches.emplace_back(glm::vec3(0.7f), "no blocker (lit)");
  legend.swatches.emplace_back(glm::vec3(0.15f), "faces away");
  return legend;
}

ColourLegend cascade_view_legend(int count) {
  ColourLegend legend;
  legend.title = "Cascades";
  legend.units = "the cascade each pixel is shaded from, its tint over the picture (nearest first)";
  for (int i = 0; i < count && i < 8; ++i)
    legend.swatches.emplace_back(over_grey(vec3_of(kCascadeTints[i]), kCascadeTintOpacity), "cascade " + std::to_string(i + 1));
  return legend;
}

float remap_view_opacity(float change) {
  const float t = std::clamp(change / kRemapFullTintChange, 0.0f, 1.0f);
  return kRemapMaxTintOpacity * t * t * (3.0f - 2.0f * t);  // GLSL's smoothstep(0, full, change)
}

ColourLegend remap_view_legend() {
  ColourLegend legend;
  legend.title = "Light-bleeding remap";
  legend.units = "light the remap removed: Chebyshev's bound minus the shadow test's result (visibility, over grey)";
  for (int i = 0; i <= kRampSteps; ++i)
    legend.ramp.push_back(over_grey(vec3_of(kRemapTint), remap_view_opacity(kRemapFullTintChange * static_cast<float>(i) / kRampSteps)));
  legend.low = "0 (no tint)";
  legend.high = number(kRemapFullTintChange) + " or more";
  return legend;
}

std::vector<std::pair<std::string, std::string>> cascade_view_defines() {
  std::string tints;
  for (const auto& c : kCascadeTints) tints += (tints.empty() ? "" : ", ") + glsl_vec3(c);
  return {{"CASCADE_TINTS", tints}, {"CASCADE_TINT_OPACITY", glsl_float(kCascadeTintOpacity)}};
}

std::vector<std::pair<std::string, std::string>> remap_view_defines() {
  return {{"REMAP_TINT", glsl_vec3(kRemapTint)},
          {"FULL_TINT_CHANGE", glsl_float(kRemapFullTintChange)},
          {"MAX_TINT_OPACITY", glsl_float(kRemapMaxTintOpacity)}};
}

ColourLegend penumbra_error_legend() {
  ColourLegend legend;
  legend.title = "Penumbra error";
  legend.units = "drawn minus true visible fraction of the light, on a lit surface";
  for (int i = 0; i <= kRampSteps; ++i) {
    const double e = kSoftDiffFullError * (2.0 * i / kRampSteps - 1.0);
    const DiffColor c = soft_diff_colour(1.0f, e);
    legend.ramp.emplace_back(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f);
  }
  legend.low = "-" + number(kSoftDiffFullError) + " or less: too dark";
  legend.high = "+" + number(kSoftDiffFullError) + " or more: too light";
  legend.ticks.emplace_back(0.5f, "0");
  const DiffColor shadowed = soft_diff_colour(0.0f, 0.0);
  legend.swatches.emplace_back(glm::vec3(shadowed[0], shadowed[1], shadowed[2]) / 255.0f, "exact, in full shadow");
  return legend;
}

}  // namespace shadowlab
