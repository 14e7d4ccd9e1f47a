// Lights with a size (light.size) in the checks: size 0 is today's hard light, every check figure the
// same; a sized light grades against the soft truth (labs/check.h: kSoftTruthStrata), and a hard shadow
// map fails its penumbra.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "labs/check.h"
#include "labs/lab.h"
#include "renderer/renderer.h"
#include "renderer/scene.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class SoftCheckTest : public GlTest {};

CheckResult check(int lab, Impl impl, std::vector<std::string> assignments) {
  Renderer renderer;
  const Scene scene = make_default_scene();
  CheckRun run;
  run.impl = impl;
  run.assignments = std::move(assignments);
  return run_lab_check(renderer, *find_lab(lab), scene, run);
}

// Every figure a check records (metrics, criteria and their limits) with light.size=0 set against the
// defaults: the same numbers, no soft figure. Labs 0 (directional), 6 (PCF), 7 (spot), 8 (point).
TEST_F(SoftCheckTest, SizeZeroChangesNoCheckFigure) {
  for (int lab : {0, 6, 7, 8}) {
    const CheckResult plain = check(lab, Impl::Solution, {});
    const CheckResult zero = check(lab, Impl::Solution, {"light.size=0"});
    ASSERT_TRUE(plain.error.empty()) << plain.error;
    EXPECT_TRUE(plain.passed()) << "lab " << lab;
    nlohmann::json a = plain.to_json(), b = zero.to_json();
    EXPECT_EQ(a["metrics"].dump().find("penumbra"), std::string::npos) << "lab " << lab;
    for (auto* j : {&a, &b}) {
      j->erase("seconds");
      j->erase("parameters");
      for (auto& [tag, m] : (*j)["metrics"].items())
        if (m.is_object()) {
          m.erase("render_ms");
          m.erase("oracle_ms");
        }
    }
    EXPECT_EQ(a, b) << "lab " << lab;
    EXPECT_EQ(zero.parameters.at("light.size").get<double>(), 0.0);
  }
}

// The same hard shadow (lab 0's solution) against a sun of 2 degrees: the fully lit region and the
// umbra stay right, the penumbra fails, by a margin printed here and quoted in the note.
TEST_F(SoftCheckTest, AHardShadowFailsTheSoftTruthsPenumbra) {
  const CheckResult sized = check(0, Impl::Solution, {"light.size=2"});
  ASSERT_TRUE(sized.error.empty()) << sized.error;
  int penumbra = 0;
  for (const auto& c : sized.criteria) {
    if (c.metric.ends_with(".penumbra_error")) {
      ++penumbra;
      std::printf("  lab 0 solution, sun 2 deg: %s = %.4f (limit %.3f)\n", c.metric.c_str(), c.value, c.limit);
      EXPECT_FALSE(c.passed()) << c.metric;
      EXPECT_GT(c.value, 2.0 * c.limit) << c.metric;
    } else if (c.metric.ends_with(".lit_error") || c.metric.ends_with(".shadow_error")) {
      EXPECT_TRUE(c.passed()) << c.metric << " " << c.value;
    }
  }
  EXPECT_GE(penumbra, 1);
  EXPECT_FALSE(sized.passed());
}

// Lab 16's PCSS (shaders/shadow/pcss.glsl) with light.size 0 is the hard test (shaders/shadow/hard.glsl)
// pixel for pixel, at the lab's parameters; with a sized sun it is not (so the comparison can fail).
TEST_F(SoftCheckTest, PcssAtSizeZeroIsTheHardTestPixelForPixel) {
  Renderer renderer;
  const Scene scene = make_default_scene();
  const Lab& lab = *find_lab(16);
  ParamSet params = lab_params(lab);
  params.set("view.debug_quad", 0.0);
  FrameRequest request;
  request.camera = OrbitCamera::framing(scene.bounds(), 30.0f, 35.0f);
  request.width = 320;
  request.height = 180;
  request.gbuffer = true;
  const Features pcss = lab.hooks(Impl::Solution);
  Features hard = pcss;
  hard.includes.erase("lab/visibility.glsl");  // the renderer's default: shaders/shadow/hard.glsl
  auto draw = [&](const Features& f, double size) {
    EXPECT_TRUE(renderer.set_features(f)) << renderer.shader_error();
    renderer.set_scene(scene);
    ParamSet p = params;
    p.set("light.size", size);
    renderer.render(p, request);
    return renderer.read_visibility();
  };
  const std::vector<float> hard0 = draw(hard, 0.0), pcss0 = draw(pcss, 0.0), pcss4 = draw(pcss, 4.0);
  ASSERT_EQ(hard0.size(), pcss0.size());
  int lit = 0, differ0 = 0, differ4 = 0;  // (0 is also the background's visibility: lit pixels are counted)
  for (std::size_t i = 0; i < hard0.size(); ++i) {
    lit += hard0[i] == 1.0f;
    differ0 += hard0[i] != pcss0[i];
    differ4 += hard0[i] != pcss4[i];
  }
  EXPECT_GT(lit, 1000);
  EXPECT_EQ(differ0, 0);
  EXPECT_GT(differ4, 100);  // the shadows' edges at 320 x 180: 319 pixels measured
  std::printf("  lab 16, %d lit pixels: PCSS at size 0 differs from the hard test at %d, at 4 deg at %d\n", lit,
              differ0, differ4);
}

}  // namespace
}  // namespace shadowlab
