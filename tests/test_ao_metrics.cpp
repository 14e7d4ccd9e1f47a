// The AO image against the truth on the interior (oracle/ao_metrics.h), on a G-buffer made by hand: a
// floor of 32 x 16 pixels with a step of one unit between columns 15 and 16, so that exactly the columns
// within kAoInteriorMargin of the step are left out.
#include "oracle/ao_metrics.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace shadowlab {
namespace {

constexpr int kFloorW = 32, kFloorH = 16;
constexpr float kFloorRadius = 0.5f;

GBuffer stepped_floor() {
  GBuffer g;
  g.width = kFloorW;
  g.height = kFloorH;
  for (int y = 0; y < kFloorH; ++y)
    for (int x = 0; x < kFloorW; ++x) {
      g.position.push_back({0.1f * static_cast<float>(x), 0.1f * static_cast<float>(y), x < 16 ? 0.0f : 1.0f});
      g.normal.push_back({0.0f, 0.0f, 1.0f});
      g.covered.push_back(1);
    }
  return g;
}

AoTruth open_truth(const GBuffer& g) {
  AoTruth t;
  t.width = g.width;
  t.height = g.height;
  t.valid.assign(g.covered.size(), 1);
  t.open.assign(g.covered.size(), 1.0f);
  return t;
}

TEST(AoMetrics, InteriorLeavesOutTheMarginAroundAStep) {
  const GBuffer g = stepped_floor();
  const auto interior = ao_interior(g, kFloorRadius);
  for (int y = 0; y < kFloorH; ++y)
    for (int x = 0; x < kFloorW; ++x) {
      // The step's pixels are 15 and 16; the margin reaches kAoInteriorMargin = 4 beyond them.
      const bool want = x <= 15 - kAoInteriorMargin - 1 || x >= 16 + kAoInteriorMargin + 1;
      EXPECT_EQ(interior[static_cast<std::size_t>(y) * kFloorW + x] != 0, want) << x << ", " << y;
    }
}

TEST(AoMetrics, BackgroundIsAnEdgeToo) {
  GBuffer g = stepped_floor();
  for (int y = 0; y < kFloorH; ++y)  // the step gone, column 0 uncovered instead
    for (int x = 0; x < kFloorW; ++x) {
      g.position[static_cast<std::size_t>(y) * kFloorW + x].z = 0.0f;
      if (x == 0) g.covered[static_cast<std::size_t>(y) * kFloorW + x] = 0;
    }
  const auto interior = ao_interior(g, kFloorRadius);
  // Columns 0 (uncovered) and 1 (beside it) are edges.
  for (int x = 0; x < kFloorW; ++x)
    EXPECT_EQ(interior[static_cast<std::size_t>(3) * kFloorW + x] != 0, x > kAoInteriorMargin + 1) << x;
}

TEST(AoMetrics, ErrorOverTheInteriorOnly) {
  const GBuffer g = stepped_floor();
  AoTruth truth = open_truth(g);
  std::vector<float> ao(g.covered.size(), 0.9f);
  for (int y = 0; y < kFloorH; ++y)
    for (int x = 11; x <= 20; ++x) ao[static_cast<std::size_t>(y) * kFloorW + x] = 0.0f;  // the margin: not graded
  truth.open[0] = 0.5f;  // one occluded pixel of the truth (below kAoOccludedTruth), AO 0.9: error 0.4
  const AoInteriorError e = ao_interior_error(g, ao, truth, kFloorRadius);
  EXPECT_EQ(e.interior_pixels, 22 * kFloorH);
  EXPECT_EQ(e.open_pixels, 22 * kFloorH - 1);
  EXPECT_EQ(e.occluded_pixels, 1);
  EXPECT_NEAR(e.open, 0.1, 1e-6);
  EXPECT_NEAR(e.occluded, 0.4, 1e-6);
  EXPECT_NEAR(e.mean, (0.1 * (22 * kFloorH - 1) + 0.4) / (22 * kFloorH), 1e-6);
  EXPECT_NEAR(e.mean_signed, (-0.1 * (22 * kFloorH - 1) + 0.4) / (22 * kFloorH), 1e-6);
}

TEST(AoMetrics, SizesMustMatch) {
  const GBuffer g = stepped_floor();
  const AoTruth truth = open_truth(g);
  EXPECT_THROW(ao_interior_error(g, std::vector<float>(3, 1.0f), truth, kFloorRadius), std::invalid_argument);
  AoTruth small = truth;
  small.open.pop_back();
  EXPECT_THROW(ao_interior_error(g, std::vector<float>(g.covered.size(), 1.0f), small, kFloorRadius), std::invalid_argument);
}

}  // namespace
}  // namespace shadowlab
