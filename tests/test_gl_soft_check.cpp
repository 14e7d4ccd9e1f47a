// Lights with a size (light.size) in the checks: size 0 is today's hard light, every check figure the
// same; a sized light grades against the soft truth (grading/check.h: kSoftTruthStrata), and a hard shadow
// map fails its penumbra.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "oracle/oracle.h"
#include "renderer/renderer.h"
#include "core/scene.h"
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

// Lab 16's parameters without the shadow map's quad, and its frame: 320 x 180 with the G-buffer.
ParamSet lab16_params() {
  ParamSet params = lab_params(*find_lab(16));
  params.set("view.debug_quad", 0.0);
  return params;
}

FrameRequest lab16_request(const Scene& scene) {
  FrameRequest request;
  request.camera = OrbitCamera::framing(scene.bounds(), 30.0f, 35.0f);
  request.width = 320;
  request.height = 180;
  request.gbuffer = true;
  return request;
}

// Lab 16's PCSS (shaders/shadow/pcss.glsl) with light.size 0 is the hard test (shaders/shadow/hard.glsl)
// pixel for pixel, at the lab's parameters; with a sized sun it is not (so the comparison can fail).
TEST_F(SoftCheckTest, PcssAtSizeZeroIsTheHardTestPixelForPixel) {
  Renderer renderer;
  const Scene scene = make_default_scene();
  const Lab& lab = *find_lab(16);
  const ParamSet params = lab16_params();
  const FrameRequest request = lab16_request(scene);
  const Features pcss = lab.hooks(Impl::Solution);
  Features hard = pcss;
  hard.shadow_test = "hard";  // shaders/shadow/hard.glsl
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

// Lab 16's debug views (pcss.view, shaders/shadow/pcss.glsl's technique_view) show what the blocker search
// found and the kernel the estimate chose, without changing what is graded. Each pixel's value is its
// red channel; read back, the two views agree with each other through the solution's estimate
// (width = distance x 2 tan(size / 2), in map texels), the stock exercise's kernel is 0 everywhere, and
// at size 0 the distance view colours exactly the hard shadow.
TEST_F(SoftCheckTest, PcssDebugViewsShowTheBlockersAndTheKernel) {
  Renderer renderer;
  const Scene scene = make_default_scene();
  const Lab& lab = *find_lab(16);
  const ParamSet params = lab16_params();
  const double range = params.get("pcss.view_range");
  const FrameRequest request = lab16_request(scene);
  struct Frame {
    std::vector<float> visibility;     // bottom row first
    std::vector<std::uint8_t> colour;  // top row first
    GBuffer g;
  };
  auto draw = [&](Impl impl, double size, const char* view) {
    EXPECT_TRUE(renderer.set_features(lab.hooks(impl))) << renderer.shader_error();
    renderer.set_scene(scene);
    ParamSet p = params;
    p.set("light.size", size);
    p.set_from_string("pcss.view", view);
    renderer.render(p, request);
    return Frame{renderer.read_visibility(), renderer.read_color(), renderer.read_gbuffer()};
  };
  const int w = request.width, h = request.height;
  // The view's colour at (x, y) of the bottom-first buffers: a ramp value t (t, t^2, 0.6 (1 - t)), -1 for
  // a grey (no blocker, or facing away) or anything else.
  auto pixel = [&](const Frame& f, int i) {  // the colour of bottom-first index i
    const int x = i % w, y = h - 1 - i / w;
    return &f.colour[4 * static_cast<std::size_t>(y * w + x)];
  };
  auto ramp = [&](const Frame& f, int i) {
    const std::uint8_t* c = pixel(f, i);
    const double t = c[0] / 255.0;
    const bool on = std::abs(c[1] - 255.0 * t * t) <= 2.0 && std::abs(c[2] - 255.0 * 0.6 * (1.0 - t)) <= 2.0;
    return on ? t : -1.0;
  };
  auto grey = [&](const Frame& f, int i, double level) {
    const std::uint8_t* c = pixel(f, i);
    const double v = 255.0 * level;  // within the conversion's rounding
    return c[0] == c[1] && c[1] == c[2] && std::abs(c[0] - v) <= 1.0;
  };

  const double size = 6.0;
  const Frame shaded = draw(Impl::Solution, size, "shadow");
  const Frame distance = draw(Impl::Solution, size, "blocker distance");
  const Frame kernel = draw(Impl::Solution, size, "kernel width");
  EXPECT_EQ(shaded.visibility, distance.visibility);  // the views change the colour only
  EXPECT_EQ(shaded.visibility, kernel.visibility);
  EXPECT_NE(shaded.colour, distance.colour);
  const int map = renderer.shadow_map_size();
  const glm::vec2 extent = renderer.light_view().world_size;
  const double texels_per_unit = std::max(map / extent.x, map / extent.y);
  int no_blocker = 0, blockers = 0, compared = 0, agree = 0;
  double worst = 0.0;
  for (int i = 0; i < w * h; ++i) {
    if (!shaded.g.covered[i]) continue;
    if (grey(distance, i, 0.7)) {  // the search found nothing in front: the whole sun is seen
      ++no_blocker;
      EXPECT_EQ(shaded.visibility[i], 1.0f) << "pixel " << i;
      continue;
    }
    const double td = ramp(distance, i), tk = ramp(kernel, i);
    if (td < 0.0) continue;  // facing away
    ++blockers;
    ASSERT_GE(tk, 0.0) << "pixel " << i << ": a blocker in one view, none in the other";
    if (td >= 0.99 || tk < 0.2) continue;  // past the view's range, or a kernel of under a texel
    const double d = td * range;
    const double texels = std::exp2(tk * std::log2(129.0)) - 1.0;
    const double expected = d * 2.0 * std::tan(size * 0.5 * M_PI / 180.0) * texels_per_unit;
    const double error = std::abs(texels - expected) / expected;
    ++compared;
    agree += error < 0.05 + 0.5 * range / 255.0 / std::max(d, 1e-6);
    worst = std::max(worst, error);
  }
  std::printf("  lab 16, sun %g deg: %d pixels without a blocker, %d with; the kernel view agrees with the "
              "distance view through the solution's estimate at %d of %d (worst relative difference %.3f)\n",
              size, no_blocker, blockers, agree, compared, worst);
  EXPECT_GT(no_blocker, 5000);
  EXPECT_GT(blockers, 2000);
  EXPECT_GT(compared, 1000);
  EXPECT_GE(agree, compared * 99 / 100);

  // The stock exercise returns 0: the same blockers, a kernel of no width.
  const Frame stock = draw(Impl::Exercise, size, "kernel width");
  int zero = 0, found = 0;
  for (int i = 0; i < w * h; ++i) {
    const double t = stock.g.covered[i] ? ramp(stock, i) : -1.0;
    if (t < 0.0) continue;
    ++found;
    zero += t == 0.0;
  }
  EXPECT_GT(found, 2000);
  EXPECT_EQ(zero, found);

  // Size 0: the hard test, and the distance view colours its shadow (covered, facing the light, visibility
  // 0) and nothing else.
  const Frame hard = draw(Impl::Solution, 0.0, "blocker distance");
  int shadowed = 0, mismatched = 0;
  for (int i = 0; i < w * h; ++i) {
    if (!hard.g.covered[i] || grey(hard, i, 0.15)) continue;
    const bool coloured = ramp(hard, i) >= 0.0;
    shadowed += coloured;
    mismatched += coloured != (hard.visibility[i] == 0.0f);
  }
  EXPECT_GT(shadowed, 1000);
  EXPECT_EQ(mismatched, 0);
}

}  // namespace
}  // namespace shadowlab
