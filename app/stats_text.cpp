#include "app/stats_text.h"

#include <cstdio>

namespace shadowlab {

std::string precision_warning(const FrameStats& stats) {
  const double share = stats.moments_negative_variance;
  if (share < 0.01) return {};
  char text[320];
  if (share >= 0.5) {
    std::snprintf(text, sizeof text,
                  "RG16F has run out of precision: %.0f %% of the shadow map's texels store a negative variance "
                  "(float16 cancellation over this light's depth range), so the shadows shown are wrong. Use RG32F.",
                  100.0 * share);
  } else {
    std::snprintf(text, sizeof text,
                  "RG16F: %.1f %% of the shadow map's texels lost their variance to float16 cancellation; Chebyshev "
                  "clamps them to the minimum variance. RG32F stores them exactly.",
                  100.0 * share);
  }
  return text;
}

}  // namespace shadowlab
