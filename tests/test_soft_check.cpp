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

}  // namespace
}  // namespace shadowlab
