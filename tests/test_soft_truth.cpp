// The soft ground truth (oracle/soft_truth.h) against closed forms: a disk light half hidden by a
// straight edge sees a circular segment of its area, so the penumbra of a half-plane blocker is known
// exactly at every point. The error of the stratified estimate is measured there, and size 0 is the
// hard truth bit for bit.
#include "oracle/soft_truth.h"

#include "oracle/metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace shadowlab {
namespace {

// The share of a unit disk beyond the chord at signed distance t from its centre (t in units of the
// radius): 1 for t <= -1, 0 for t >= 1.
double segment_beyond(double t) {
  if (t <= -1.0) return 1.0;
  if (t >= 1.0) return 0.0;
  return (std::acos(t) - t * std::sqrt(1.0 - t * t)) / std::numbers::pi;
}

// A blocker over x < 0 at height kH (a large quad, edge along z at x = 0), nothing else.
constexpr float kH = 2.0f;
Scene half_plane_scene() {
  Scene s;
  Mesh m;
  m.positions = {{-50.0f, kH, -50.0f}, {0.0f, kH, -50.0f}, {0.0f, kH, 50.0f}, {-50.0f, kH, 50.0f}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.indices = {0, 1, 2, 0, 2, 3};
  s.meshes.push_back(m);
  return s;
}

// Receivers on the ground (y = 0, normal up) along x in [x0, x1], z = 0.
GBuffer receivers(int n, float x0, float x1) {
  GBuffer g;
  g.width = n;
  g.height = 1;
  for (int i = 0; i < n; ++i) {
    g.position.push_back({x0 + (x1 - x0) * (static_cast<float>(i) + 0.5f) / static_cast<float>(n), 0.0f, 0.0f});
    g.normal.push_back({0, 1, 0});
    g.covered.push_back(1);
  }
  return g;
}

struct Errors {
  double max = 0.0, mean = 0.0;
  int penumbra = 0;  // receivers strictly inside the penumbra
};

// A sun straight overhead of angular diameter `size`: at ground point x the ray to disk offset a (at
// unit height) crosses the blocker's height at x + a kH, so the free part of the disk is a > -x / kH.
Errors sun_errors(float size, int strata, int n, bool as_hard = false, SoftSampling sampling = SoftSampling::EdgeRefined) {
  const Scene scene = half_plane_scene();
  const Oracle oracle(scene);
  const float r = std::tan(0.5f * size);
  const GBuffer g = receivers(n, -1.5f * kH * r, 1.5f * kH * r);
  OracleLight sun;
  sun.to_light = {0, 1, 0};
  const SoftTruth t = evaluate_soft(oracle, g, sun, as_hard ? 0.0f : size, strata, sampling);
  Errors e;
  for (int i = 0; i < n; ++i) {
    const double x = g.position[static_cast<std::size_t>(i)].x;
    const double want = segment_beyond(-x / (kH * r));
    const double err = std::abs(t.visible[static_cast<std::size_t>(i)] - want);
    e.max = std::max(e.max, err);
    e.mean += err / n;
    e.penumbra += want > 0.0 && want < 1.0;
  }
  return e;
}

TEST(SoftTruth, ConcentricMapKeepsAreas) {
  // A uniform grid in the square lands uniformly on the disk: a quarter of the points within radius
  // 1/2, E[r^2] = 1/2, none outside.
  constexpr int kN = 200;
  int inner = 0;
  double r2 = 0.0;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const glm::vec2 p = concentric_disk((i + 0.5f) / kN, (j + 0.5f) / kN);
      const float d2 = glm::dot(p, p);
      ASSERT_LE(d2, 1.0f + 1e-6f);
      inner += d2 < 0.25f;
      r2 += d2;
    }
  EXPECT_NEAR(inner / double(kN * kN), 0.25, 0.005);
  EXPECT_NEAR(r2 / (kN * kN), 0.5, 0.001);
}

// Measured with 400 receivers spread over 1.5 penumbra half-widths on either side of the edge's shadow
// (two thirds of them in the penumbra), the same at 0.5 and 5 degrees (the geometry scales): 8 x 8
// samples err 0.0090 on average and 0.048 at worst; 16 x 16 samples 0.0031 and 0.019. The hard truth (the
// light's size ignored) errs 0.14 on average there. The limits sit at about 1.6 times the measured errors.
TEST(SoftTruth, SunPenumbraOfAnEdgeIsTheCircularSegment) {
  for (const float degrees : {0.5f, 5.0f}) {
    const float size = glm::radians(degrees);
    const Errors e8 = sun_errors(size, 8, 400);
    EXPECT_GT(e8.penumbra, 250) << degrees;
    EXPECT_LT(e8.mean, 0.014) << degrees;
    EXPECT_LT(e8.max, 0.075) << degrees;
    const Errors e16 = sun_errors(size, 16, 400);
    EXPECT_LT(e16.mean, 0.005) << degrees;
    EXPECT_LT(e16.max, 0.03) << degrees;
    EXPECT_LT(e16.mean, e8.mean) << degrees;  // more samples, less error
    const Errors hard = sun_errors(size, 16, 400, true);
    EXPECT_GT(hard.mean, 0.1) << degrees;  // the closed form does tell a sized light from a point
    std::printf("sun %.1f deg: 8x8 mean %.4f max %.4f; 16x16 mean %.4f max %.4f; hard truth mean %.4f\n", degrees,
                e8.mean, e8.max, e16.mean, e16.max, hard.mean);
  }
}

// A disk light of radius r at c, facing the receiver p: the plane through p and the blocker's edge cuts
// the disk along a chord; the side where the segment passes the edge at x > 0 is free. 300 receivers
// across the penumbra (134 inside it), 12 x 12 samples: mean error 0.0035, largest 0.030.
TEST(SoftTruth, PositionalPenumbraOfAnEdgeIsTheCircularSegment) {
  const Scene scene = half_plane_scene();
  const Oracle oracle(scene);
  OracleLight lamp;
  lamp.positional = true;
  lamp.position = {0.3f, 5.0f, 0.0f};
  const float r = 0.4f;
  const GBuffer g = receivers(300, -0.8f, 0.4f);  // the penumbra is about [-0.47, 0.07]
  const SoftTruth t = evaluate_soft(oracle, g, lamp, r, 12);
  double mean = 0.0, worst = 0.0;
  int penumbra = 0;
  for (std::size_t i = 0; i < g.position.size(); ++i) {
    const glm::dvec3 p(g.position[i]), c(lamp.position);
    const glm::dvec3 m(-kH, -p.x, 0.0);  // normal of the plane through p and the edge line {(0, kH, z)}
    const glm::dvec3 mh = glm::normalize(m), w = glm::normalize(c - p);
    const double d = glm::dot(mh, c - p);                                     // the centre's distance from it
    const double in_plane = std::sqrt(std::max(0.0, 1.0 - glm::dot(mh, w) * glm::dot(mh, w)));
    // Free where m . (q - p) < 0: the share of the disk short of the chord at -d / (in_plane r).
    const double want = 1.0 - segment_beyond(-d / (in_plane * r));
    const double err = std::abs(t.visible[i] - want);
    mean += err / static_cast<double>(g.position.size());
    worst = std::max(worst, err);
    penumbra += want > 0.0 && want < 1.0;
  }
  std::printf("positional r %.2f: 12x12 mean %.4f max %.4f over %d penumbra receivers\n", r, mean, worst, penumbra);
  EXPECT_GT(penumbra, 100);
  EXPECT_LT(mean, 0.006);  // measured: 0.0035
  EXPECT_LT(worst, 0.05);  // measured: 0.030
}

// The 120 x 120 ground grid under the default scene (a sphere, a box and a thin pillar over a floor).
GBuffer ground_grid() {
  GBuffer g;
  g.width = 120;
  g.height = 120;
  for (int j = 0; j < 120; ++j)
    for (int i = 0; i < 120; ++i) {
      g.position.push_back({-6.0f + 0.1f * i + 0.05f, 0.0f, -6.0f + 0.1f * j + 0.05f});
      g.normal.push_back({0, 1, 0});
      g.covered.push_back(1);
    }
  return g;
}

// A sun and a lamp over that grid, both casting the default scene's shadows onto it.
OracleLight grid_sun() {
  OracleLight sun;
  sun.to_light = glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f));
  return sun;
}
OracleLight grid_lamp() {
  OracleLight lamp;
  lamp.positional = true;
  lamp.position = {-2.0f, 6.0f, 1.5f};
  return lamp;
}

// Size 0 is today's hard light: the same rays as Oracle::evaluate, so the same answer at every pixel,
// on a scene with curved and flat casters, for a sun and a lamp.
TEST(SoftTruth, SizeZeroIsTheHardTruth) {
  const Scene scene = make_default_scene();
  const Oracle oracle(scene);
  const GBuffer g = ground_grid();
  const OracleLight sun = grid_sun(), lamp = grid_lamp();
  for (const OracleLight& light : {sun, lamp}) {
    const Truth hard = oracle.evaluate(g, light);
    const SoftTruth soft = evaluate_soft(oracle, g, light, 0.0f, 8);
    EXPECT_EQ(soft.samples, 1);
    int shadowed = 0;
    for (std::size_t i = 0; i < g.position.size(); ++i) {
      ASSERT_EQ(soft.valid[i], hard.valid[i]) << i;
      ASSERT_EQ(soft.visible[i], hard.lit[i] ? 1.0f : 0.0f) << i;
      shadowed += hard.valid[i] && !hard.lit[i];
    }
    EXPECT_GT(shadowed, 100);  // the scene does cast shadows on the grid
  }
}

// EdgeRefined gives the penumbra the very estimate Full sampling gives (the same samples), so where the
// pilots see the edge nothing changes. On the closed forms' strips every receiver agrees bit for bit,
// and the errors against the circular segment are the ones measured above.
TEST(SoftTruth, EdgeRefinedIsFullSamplingAcrossAnEdge) {
  const Scene scene = half_plane_scene();
  const Oracle oracle(scene);
  OracleLight sun;
  OracleLight lamp;
  lamp.positional = true;
  lamp.position = {0.3f, 5.0f, 0.0f};
  const float r = std::tan(0.5f * glm::radians(5.0f));
  const GBuffer sun_strip = receivers(400, -3.0f * kH * r, 3.0f * kH * r);  // penumbra and as much again
  const GBuffer lamp_strip = receivers(300, -1.2f, 0.8f);
  for (const auto& [light, size, g] : {std::tuple{sun, glm::radians(5.0f), sun_strip}, std::tuple{lamp, 0.4f, lamp_strip}}) {
    const SoftTruth full = evaluate_soft(oracle, g, light, size, 16, SoftSampling::Full);
    const SoftTruth edge = evaluate_soft(oracle, g, light, size, 16, SoftSampling::EdgeRefined);
    EXPECT_EQ(full.refined, g.position.size());
    EXPECT_GT(edge.refined, 0u);
    EXPECT_LT(edge.refined, g.position.size() * 3 / 4) << "the strips reach beyond the penumbra on both sides";
    EXPECT_LT(edge.rays, full.rays * 3 / 4);
    ASSERT_EQ(edge.valid, full.valid);
    for (std::size_t i = 0; i < g.position.size(); ++i) ASSERT_EQ(edge.visible[i], full.visible[i]) << i;
  }
  const Errors e = sun_errors(glm::radians(5.0f), 16, 400, false, SoftSampling::Full);
  const Errors refined = sun_errors(glm::radians(5.0f), 16, 400);
  EXPECT_EQ(e.mean, refined.mean);
  EXPECT_EQ(e.max, refined.max);
}

// On a scene of several casters the refinement samples in full only near the penumbrae, and every pixel
// it leaves to the pilots is one Full sampling also finds wholly lit or wholly shadowed. Measured on the
// 14,400 ground pixels (sun 2 and 8 degrees, lamp radius 0.25 and 1): 137, 674, 800 and 3,335 penumbra
// pixels; 1,893, 2,404, 2,978 and 5,461 sampled in full; rays 0.20, 0.23, 0.27 and 0.45x Full's; no pixel
// differs from Full. (With neighbours only 1 pixel away, the lamp of radius 1 left one pixel off by 1/256.)
// The limits allow what a thin caster can hide from every pilot: a 0.1 % share of the pixels, by <= 0.01.
TEST(SoftTruth, EdgeRefinedAgreesWithFullSamplingOnTheDefaultScene) {
  const Scene scene = make_default_scene();
  const Oracle oracle(scene);
  const GBuffer g = ground_grid();
  const OracleLight sun = grid_sun(), lamp = grid_lamp();
  for (const auto& [light, size] : {std::pair{sun, glm::radians(2.0f)}, std::pair{sun, glm::radians(8.0f)},
                                    std::pair{lamp, 0.25f}, std::pair{lamp, 1.0f}}) {
    const SoftTruth full = evaluate_soft(oracle, g, light, size, 16, SoftSampling::Full);
    const SoftTruth edge = evaluate_soft(oracle, g, light, size, 16);
    int differ = 0, penumbra = 0;
    float worst = 0.0f;
    for (std::size_t i = 0; i < g.position.size(); ++i) {
      differ += edge.visible[i] != full.visible[i];
      worst = std::max(worst, std::abs(edge.visible[i] - full.visible[i]));
      penumbra += full.visible[i] > 0.0f && full.visible[i] < 1.0f;
    }
    std::printf("%s size %.3f: %d penumbra px, refined %zu of %zu, rays %.2fx Full's, %d differ (worst %.3f)\n",
                light.positional ? "lamp" : "sun", size, penumbra, edge.refined, g.position.size(),
                static_cast<double>(edge.rays) / static_cast<double>(full.rays), differ, worst);
    EXPECT_GT(penumbra, 100);
    EXPECT_LE(differ, static_cast<int>(g.position.size() / 1000));
    EXPECT_LE(worst, 0.01f);
    EXPECT_LT(edge.rays, full.rays / 2);
  }
}

// For a light of size 0 the soft error is the hard error the checks and the benchmark use: compare()'s
// mean over interior and edge pixels together, with NaN, negative and above-one values among them.
TEST(SoftMetrics, SizeZeroIsTheHardError) {
  const Scene scene = make_default_scene();
  const Oracle oracle(scene);
  const GBuffer g = ground_grid();
  OracleLight sun = grid_sun();
  sun.texel_world_size = 0.05f;
  sun.image_x = {1, 0, 0};
  sun.image_y = {0, 0, 1};
  const Truth hard = oracle.evaluate(g, sun);
  const SoftTruth soft = evaluate_soft(oracle, g, sun, 0.0f, 16);
  std::vector<float> visibility(g.position.size());
  for (std::size_t i = 0; i < visibility.size(); ++i) {
    const float lit = hard.lit[i] ? 1.0f : 0.0f;
    switch (i % 7) {
      case 0: visibility[i] = std::nanf(""); break;
      case 1: visibility[i] = 1.0f - lit; break;
      case 2: visibility[i] = lit + 0.3f; break;
      case 3: visibility[i] = lit - 0.2f; break;
      case 4: visibility[i] = 0.5f; break;
      default: visibility[i] = lit;
    }
  }
  const Metrics m = compare(hard, visibility);
  const SoftMetrics sm = compare_soft(soft, visibility);
  ASSERT_GT(m.edge_pixels, 100u);
  ASSERT_GT(m.interior_shadowed, 100u);
  EXPECT_EQ(sm.valid_pixels, m.valid_pixels);
  EXPECT_EQ(sm.penumbra_pixels, 0u);
  const double interior = static_cast<double>(m.interior_lit + m.interior_shadowed);
  const double edge = static_cast<double>(m.edge_pixels);
  EXPECT_NEAR(sm.mae, (m.mae_interior * interior + m.mae_edge * edge) / (interior + edge), 1e-12);
  EXPECT_NEAR(sm.too_dark + sm.too_light, sm.mae, 1e-12);
}

TEST(SoftMetrics, SplitsTooDarkFromTooLightAndColoursThem) {
  SoftTruth t;
  t.width = 3;
  t.height = 2;
  t.valid = {1, 1, 1, 1, 1, 0};
  t.visible = {1.0f, 0.5f, 0.25f, 0.0f, 0.5f, 0.0f};
  const std::vector<float> v = {1.0f, 0.25f, 0.5f, 0.1f, std::nanf(""), 0.7f};
  const SoftMetrics m = compare_soft(t, v);
  EXPECT_EQ(m.valid_pixels, 5u);
  EXPECT_EQ(m.penumbra_pixels, 3u);
  // Errors: 0, -0.25, +0.25, +0.1, and a NaN where the fraction is 0.5 counts as 0 (too dark by 0.5).
  EXPECT_NEAR(m.too_dark, (0.25 + 0.5) / 5, 1e-9);
  EXPECT_NEAR(m.too_light, (0.25 + 0.1) / 5, 1e-7);
  EXPECT_NEAR(m.mae, 1.1 / 5, 1e-9);
  EXPECT_NEAR(m.mae_penumbra, (0.25 + 0.25 + 0.5) / 3, 1e-9);
  const auto image = soft_diff_image(t, v);
  ASSERT_EQ(image.size(), 3u * 2u * 4u);
  auto at = [&](int x, int y_from_bottom) { return &image[static_cast<std::size_t>(((1 - y_from_bottom) * 3 + x) * 4)]; };
  EXPECT_EQ(at(0, 0)[0], kDiffLit[0]);  // exact and lit: the lit grey
  EXPECT_EQ(at(1, 0)[0], kDiffAcne[0]);  // too dark by a full kSoftDiffFullError: red
  EXPECT_EQ(at(1, 0)[1], kDiffAcne[1]);
  EXPECT_EQ(at(2, 0)[2], kDiffLeak[2]);  // too light by 0.25: blue
  EXPECT_GT(at(0, 1)[2], at(0, 1)[0]);   // too light by 0.1: toward blue, not all the way
  EXPECT_LT(at(0, 1)[2], kDiffLeak[2]);
  EXPECT_EQ(at(1, 1)[0], kDiffAcne[0]);  // NaN: the wrong answer, here too dark
  EXPECT_EQ(at(2, 1)[0], 0);  // invalid: black
  EXPECT_EQ(at(2, 1)[3], 255);
  SoftTruth wrong = t;
  wrong.visible.pop_back();
  EXPECT_THROW(compare_soft(wrong, v), std::invalid_argument);
  EXPECT_THROW(soft_diff_image(t, std::vector<float>(5)), std::invalid_argument);
}

TEST(SoftTruth, RefusesWhatItCannotMean) {
  const Scene scene = half_plane_scene();
  const Oracle oracle(scene);
  const GBuffer g = receivers(4, -1, 1);
  OracleLight sun;
  EXPECT_THROW(evaluate_soft(oracle, g, sun, -0.1f, 8), std::invalid_argument);
  EXPECT_THROW(evaluate_soft(oracle, g, sun, std::nanf(""), 8), std::invalid_argument);
  EXPECT_THROW(evaluate_soft(oracle, g, sun, 4.0f, 8), std::invalid_argument);  // wider than a half-space
  EXPECT_THROW(evaluate_soft(oracle, g, sun, 0.1f, 0), std::invalid_argument);
  GBuffer short_arrays = g;
  short_arrays.normal.pop_back();
  EXPECT_THROW(evaluate_soft(oracle, short_arrays, sun, 0.1f, 8), std::invalid_argument);
}

}  // namespace
}  // namespace shadowlab
