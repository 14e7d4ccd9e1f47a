// Grading against a light with a size (oracle/metrics.h: soften, add_soft_metrics): the penumbra's
// figures from hand-made truths, and the hard truth narrowed to the fully lit region and the umbra.
#include "oracle/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace shadowlab {
namespace {

// Five pixels: lit (1), umbra (0), two in the penumbra (0.25, 0.75), and one not valid.
SoftTruth five_soft() {
  SoftTruth s;
  s.width = 5;
  s.height = 1;
  s.samples = 256;
  s.valid = {1, 1, 1, 1, 0};
  s.visible = {1.0f, 0.0f, 0.25f, 0.75f, 0.0f};
  return s;
}

// The hard truth of the same pixels (the centre ray): lit, shadowed, shadowed, lit; all interior.
Truth five_hard() {
  Truth t;
  t.width = 5;
  t.height = 1;
  t.valid = {1, 1, 1, 1, 0};
  t.lit = {1, 0, 0, 1, 0};
  t.interior = {1, 1, 1, 1, 0};
  return t;
}

TEST(SoftMetrics, PenumbraErrorAndItsSides) {
  Metrics m;
  // Exact on lit and umbra; the penumbra drawn hard (0 and 1): off by 0.25 each, one too dark, one too light.
  add_soft_metrics(m, five_soft(), {1.0f, 0.0f, 0.0f, 1.0f, 0.5f});
  EXPECT_TRUE(m.soft);
  EXPECT_EQ(m.penumbra_pixels, 2u);
  EXPECT_DOUBLE_EQ(m.penumbra_error, 0.25);
  EXPECT_DOUBLE_EQ(m.soft_too_dark, 0.25 / 4.0);  // over the four valid pixels
  EXPECT_DOUBLE_EQ(m.soft_too_light, 0.25 / 4.0);
  EXPECT_DOUBLE_EQ(m.soft_mean_error, 0.5 / 4.0);  // the invalid pixel does not count
  // The fractions themselves: no error at all.
  Metrics exact;
  add_soft_metrics(exact, five_soft(), {1.0f, 0.0f, 0.25f, 0.75f, 0.9f});
  EXPECT_DOUBLE_EQ(exact.penumbra_error, 0.0);
  EXPECT_DOUBLE_EQ(exact.soft_mean_error, 0.0);
}

TEST(SoftMetrics, NanIsTheFarthestAnswer) {
  Metrics m;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  add_soft_metrics(m, five_soft(), {1.0f, 0.0f, nan, nan, 0.0f});
  // 0.25 is taken as 1 (off by 0.75), 0.75 as 0 (off by 0.75).
  EXPECT_DOUBLE_EQ(m.penumbra_error, 0.75);
  EXPECT_DOUBLE_EQ(m.soft_too_light, 0.75 / 4.0);
}

TEST(SoftMetrics, SoftenKeepsOnlyLitAndUmbraInterior) {
  const Truth t = soften(five_hard(), five_soft());
  EXPECT_EQ(t.interior, (std::vector<std::uint8_t>{1, 1, 0, 0, 0}));
  EXPECT_EQ(t.lit, (std::vector<std::uint8_t>{1, 0, 0, 1, 0}));
  // A pixel in the hard truth's edge band stays out of the interior even where the light is all seen.
  Truth hard = five_hard();
  hard.interior[0] = 0;
  EXPECT_EQ(soften(hard, five_soft()).interior[0], 0);
  // Graded with compare(): a hard answer is exact on the interior, its penumbra error is not hidden.
  Metrics m = compare(t, {1.0f, 0.0f, 0.0f, 1.0f, 0.0f});
  add_soft_metrics(m, five_soft(), {1.0f, 0.0f, 0.0f, 1.0f, 0.0f});
  EXPECT_EQ(m.interior_lit, 1u);
  EXPECT_EQ(m.interior_shadowed, 1u);
  EXPECT_DOUBLE_EQ(m.lit_error, 0.0);
  EXPECT_DOUBLE_EQ(m.shadow_error, 0.0);
  EXPECT_DOUBLE_EQ(m.penumbra_error, 0.25);
}

TEST(SoftMetrics, SoftFiguresOnlyInTheJsonOfASoftGrade) {
  Metrics hard;
  EXPECT_FALSE(to_json(hard).contains("penumbra_error"));
  Metrics soft;
  add_soft_metrics(soft, five_soft(), {1.0f, 0.0f, 0.0f, 1.0f, 0.0f});
  EXPECT_DOUBLE_EQ(to_json(soft).at("penumbra_error").get<double>(), 0.25);
}

TEST(SoftMetrics, SizesThatDoNotMatchThrow) {
  Metrics m;
  EXPECT_THROW(add_soft_metrics(m, five_soft(), {1.0f}), std::invalid_argument);
  Truth small = five_hard();
  small.width = 4;
  small.valid.pop_back();
  small.lit.pop_back();
  small.interior.pop_back();
  EXPECT_THROW(soften(small, five_soft()), std::invalid_argument);
}

}  // namespace
}  // namespace shadowlab
