// What the debug views need said in words: each debug quad's label and each false-colour view's legend.
// The renderer collects them while it draws (a quad's label is given where the quad is placed,
// DebugQuadArea::place; a legend comes from the same function that gives its shader the mapping's
// range), and the app draws them over the view with ImGui, in the window and in `render --panel`
// pictures alike (app/view_annotations.h).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/params.h"

namespace shadowlab {

// One debug quad as drawn: its viewport in the frame (GL convention: x, y from the bottom left, pixels)
// and what it shows, in words a student reads from the back of the hall.
struct DebugQuadLabel {
  int x = 0, y = 0, width = 0, height = 0;
  std::string text;
};

// A colour bar: the mapping value -> colour of a false-colour view, sampled evenly from the low end to
// the high end, with the values at its ends in the view's units.
struct ColourLegend {
  std::string title;                    // "PCSS kernel width"
  std::string units;                    // "map texels, log scale"
  std::vector<glm::vec3> ramp;          // colours (0-1) at evenly spaced points, low end first
  std::string low, high;                // the values at the ends, with their units ("0", "128 texels")
  std::vector<std::pair<float, std::string>> ticks;  // values inside, at their place along the bar (0-1)
  // Colours outside the ramp ("no blocker"); without a ramp, a categorical view's colours (the cascades).
  std::vector<std::pair<glm::vec3, std::string>> swatches;
};

// A frame's words, in drawing order.
struct DebugAnnotations {
  std::vector<DebugQuadLabel> quads;
  std::vector<ColourLegend> legends;
  void clear() {
    quads.clear();
    legends.clear();
  }
};

// PCSS's debug view (pcss.view, shaders/shadow/pcss.glsl technique_view): the colour of t in [0, 1]
// (the shader's own formula, t itself in the red channel), and the value shown at t = 1, which the lit
// pass sets as u_pcss_view_range: the blockers' distance pcss.view_range (world units), or the kernel
// width 2 x kPcssMaxRadiusTexels (map texels, on the log scale log2(1 + w) / log2(1 + that)).
inline constexpr float kPcssMaxRadiusTexels = 64.0f;  // = shaders/shadow/pcss.glsl PCSS_MAX_RADIUS_TEXELS
glm::vec3 pcss_view_colour(float t);
float pcss_view_range(const ParamSet& params);
// The legend of the view the parameters choose; none with pcss.view = shadow.
std::optional<ColourLegend> pcss_view_legend(const ParamSet& params);

// Lab 12's cascade view (csm.show_cascades, shaders/csm/cascade_view.frag): each pixel tinted by its
// cascade, the tint blended over the picture at kCascadeTintOpacity. The shader takes both as defines
// (lit_view_defines), the legend names each colour.
inline constexpr float kCascadeTints[8][3] = {{1.0f, 0.2f, 0.2f},  {0.2f, 1.0f, 0.2f}, {0.25f, 0.45f, 1.0f},
                                              {1.0f, 0.9f, 0.1f},  {1.0f, 0.2f, 1.0f}, {0.1f, 1.0f, 1.0f},
                                              {1.0f, 0.6f, 0.1f},  {0.7f, 0.7f, 0.7f}};
inline constexpr float kCascadeTintOpacity = 0.35f;
ColourLegend cascade_view_legend(int count);

// The variance shadow maps' remap view (vsm.show_remap, shaders/vsm/remap_view.frag): where the
// light-bleeding remap removed light, kRemapTint blended over the picture at an opacity rising
// smoothly from 0 to kRemapMaxTintOpacity as the change grows to kRemapFullTintChange.
inline constexpr float kRemapTint[3] = {1.0f, 0.0f, 0.85f};
inline constexpr float kRemapFullTintChange = 0.1f;
inline constexpr float kRemapMaxTintOpacity = 0.8f;
float remap_view_opacity(float change);  // the shader's: kRemapMaxTintOpacity x smoothstep(0, full, change)
ColourLegend remap_view_legend();

// The defines that give those two views' shaders their constants (name, GLSL value).
std::vector<std::pair<std::string, std::string>> cascade_view_defines();
std::vector<std::pair<std::string, std::string>> remap_view_defines();

// The Penumbra error view (soft_diff_image, oracle/metrics.h): the signed error from -kSoftDiffFullError
// (drawn too dark) to +kSoftDiffFullError (too light), over a fully lit surface.
ColourLegend penumbra_error_legend();

}  // namespace shadowlab
