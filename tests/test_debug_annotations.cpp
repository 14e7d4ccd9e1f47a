// The false-colour legends (renderer/debug_annotations.h) against the mappings they explain: PCSS's debug
// view (shaders/shadow/pcss.glsl technique_view) and the Penumbra error picture (soft_diff_image). No
// GL: tests/test_gl_debug_annotations.cpp checks what the renderer records while it draws.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "renderer/debug_annotations.h"
#include "oracle/metrics.h"
#include "core/technique_params.h"

namespace shadowlab {
namespace {

ParamSet pcss_params(const std::string& view, double range = 4.0) {
  ParamSet p(technique_param_specs({"pcss.view", "pcss.view_range"}));
  p.set_from_string("pcss.view", view);
  p.set("pcss.view_range", range);
  return p;
}

// The shader's cap, read from its source: the legend's high end is twice it.
float shader_cap() {
  std::ifstream in(std::string(SHADOWLAB_SOURCE_DIR) + "/shaders/shadow/pcss.glsl");
  std::stringstream text;
  text << in.rdbuf();
  std::smatch m;
  const std::string s = text.str();
  if (!std::regex_search(s, m, std::regex(R"(const float PCSS_MAX_RADIUS_TEXELS = ([0-9.]+);)"))) return -1.0f;
  return std::stof(m[1]);
}

TEST(DebugAnnotations, PcssLegendIsTheShadersRampAndRange) {
  EXPECT_FALSE(pcss_view_legend(pcss_params("shadow")).has_value());

  const ParamSet blockers = pcss_params("blocker distance", 2.5);
  EXPECT_FLOAT_EQ(pcss_view_range(blockers), 2.5f);  // what the lit pass sets as u_pcss_view_range
  const auto b = pcss_view_legend(blockers);
  ASSERT_TRUE(b.has_value());
  EXPECT_EQ(b->low, "0");
  EXPECT_NE(b->high.find("2.5"), std::string::npos) << b->high;
  EXPECT_FALSE(b->units.empty());
  ASSERT_GE(b->ramp.size(), 2u);
  // The shader's colours at both ends: dark blue (0, 0, 0.6) and yellow (1, 1, 0).
  EXPECT_EQ(b->ramp.front(), glm::vec3(0.0f, 0.0f, 0.6f));
  EXPECT_EQ(b->ramp.back(), glm::vec3(1.0f, 1.0f, 0.0f));
  EXPECT_EQ(b->ramp[b->ramp.size() / 2], pcss_view_colour(0.5f));

  const ParamSet kernel = pcss_params("kernel width");
  EXPECT_EQ(shader_cap(), kPcssMaxRadiusTexels) << "shaders/shadow/pcss.glsl's cap and the legend's differ";
  EXPECT_FLOAT_EQ(pcss_view_range(kernel), 2.0f * kPcssMaxRadiusTexels);
  const auto k = pcss_view_legend(kernel);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(k->high.rfind("128 ", 0), 0u) << k->high;
  // 16 texels sits where the shader puts it: log2(17) / log2(129), about 0.58.
  bool sixteen = false;
  for (const auto& [t, text] : k->ticks)
    if (text == "16") {
      sixteen = true;
      EXPECT_NEAR(t, 0.583, 0.002);
    }
  EXPECT_TRUE(sixteen);
}

TEST(DebugAnnotations, PenumbraLegendIsTheDiffPicturesMapping) {
  const ColourLegend legend = penumbra_error_legend();
  ASSERT_GE(legend.ramp.size(), 3u);
  // Its ends are the picture's colours at a full error (too dark: red; too light: blue), its middle the lit grey.
  EXPECT_EQ(legend.ramp.front(), glm::vec3(kDiffAcne[0], kDiffAcne[1], kDiffAcne[2]) / 255.0f);
  EXPECT_EQ(legend.ramp.back(), glm::vec3(kDiffLeak[0], kDiffLeak[1], kDiffLeak[2]) / 255.0f);
  EXPECT_EQ(legend.ramp[legend.ramp.size() / 2], glm::vec3(kDiffLit[0], kDiffLit[1], kDiffLit[2]) / 255.0f);
  EXPECT_NE(legend.low.find("-0.25"), std::string::npos) << legend.low;
  EXPECT_NE(legend.high.find("+0.25"), std::string::npos) << legend.high;
  EXPECT_FALSE(legend.units.empty());
}

// The overlays' shaders take their colours and ranges from the constants the legends read: no literal
// copy is left in the shader files.
TEST(DebugAnnotations, OverlayViewsTakeTheirColoursFromTheLegendsConstants) {
  auto source = [](const char* file) {
    std::ifstream in(std::string(SHADOWLAB_SOURCE_DIR) + "/" + file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const std::string cascade = source("shaders/csm/cascade_view.frag"), remap = source("shaders/vsm/remap_view.frag");
  EXPECT_NE(cascade.find("vec3[8](CASCADE_TINTS)"), std::string::npos);
  EXPECT_EQ(cascade.find("0.35"), std::string::npos) << "the opacity is kCascadeTintOpacity";
  EXPECT_EQ(remap.find("const float FULL_TINT_CHANGE"), std::string::npos);
  const auto cascade_defines = cascade_view_defines();
  ASSERT_EQ(cascade_defines.size(), 2u);
  EXPECT_EQ(cascade_defines[0].second.rfind("vec3(1.0, 0.200000003, 0.200000003), vec3(0.200000003, 1.0", 0), 0u)
      << cascade_defines[0].second;
  EXPECT_EQ(cascade_defines[1].second, "0.349999994");
  const auto remap_defines = remap_view_defines();
  ASSERT_EQ(remap_defines.size(), 3u);
  EXPECT_EQ(remap_defines[1], (std::pair<std::string, std::string>{"FULL_TINT_CHANGE", "0.100000001"}));

  const ColourLegend cascades = cascade_view_legend(3);
  ASSERT_EQ(cascades.swatches.size(), 3u);
  EXPECT_EQ(cascades.swatches[1].second, "cascade 2");
  EXPECT_TRUE(cascades.ramp.empty());
  const ColourLegend bleeding = remap_view_legend();
  EXPECT_EQ(bleeding.ramp.front(), glm::vec3(0.5f));  // no change: no tint
  EXPECT_FLOAT_EQ(remap_view_opacity(kRemapFullTintChange), kRemapMaxTintOpacity);
  EXPECT_NE(bleeding.high.find("0.1"), std::string::npos);
}

}  // namespace
}  // namespace shadowlab
