// PCF and VSM with a filter width matched to the light's size (pcf.match_light, vsm.match_light;
// FrameLight::matched_filter_radius): the kernel spans the penumbra 2 d tan(size / 2) that a blocker d
// above its receiver casts under a sun. Checked on what the renderer draws: PCF's compiled-in radius
// against the formula on the frame's own light box, the VSM blur redone when (and only when) the matched
// width changes, and, against the exact soft truth, the matched kernel nearer the true penumbra than a
// kernel of any fixed size over suns of several sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <string>

#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/renderer.h"
#include "core/scene.h"
#include "oracle/soft_truth.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class MatchedFilterTest : public GlTest {};

int drawn_pcf_radius(const Renderer& r) {
  for (const auto& [name, value] : r.drawn_lit_constants())
    if (name == "u_pcf_radius") return std::stoi(value);
  return -1;
}

// The formula, from the frame's ortho box: texels of the mean of its x and y extents.
int expected_radius(const Renderer& r, double degrees, double distance, int map_size) {
  const glm::mat4& p = r.light_view().projection;
  const double texel = 0.5 * (2.0 / std::abs(p[0][0]) + 2.0 / std::abs(p[1][1])) / map_size;
  const double width = 2.0 * distance * std::tan(0.5 * degrees * 3.14159265358979 / 180.0);
  return static_cast<int>(std::clamp(std::round((width / texel - 1.0) / 2.0), 0.0, 12.0));
}

FrameRequest small_request(const Renderer& r, const ParamSet& params) {
  FrameRequest request;
  request.camera = frame_scene_camera(r.scene(), params);
  request.width = 320;
  request.height = 180;
  return request;
}

TEST_F(MatchedFilterTest, PcfKernelSpansThePenumbraAtTheMatchedDistance) {
  const Lab& lab = *find_lab(6);
  Renderer r;
  ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
  r.set_scene(make_default_scene());
  ParamSet params = lab_params(lab);
  params.set_from_string("shadow.map_size", "2048");
  params.set_from_string("pcf.kernel", "3");
  const FrameRequest request = small_request(r, params);
  r.render(params, request);
  EXPECT_EQ(drawn_pcf_radius(r), 1) << "pcf.kernel 3 without matching";
  params.set("pcf.match_light", 1.0);
  r.render(params, request);
  EXPECT_EQ(drawn_pcf_radius(r), 1) << "light.size 0: nothing to match, pcf.kernel decides";
  int last = 0;
  for (double degrees : {0.5, 1.0, 3.0, 5.0}) {
    params.set("light.size", degrees);
    for (double distance : {0.5, 1.0, 2.0}) {
      params.set("pcf.match_distance", distance);
      r.render(params, request);
      const int want = expected_radius(r, degrees, distance, 2048);
      EXPECT_EQ(drawn_pcf_radius(r), want) << degrees << " deg, d " << distance;
      if (distance == 1.0) {
        EXPECT_GE(want, last);
        last = want;
      }
    }
  }
  EXPECT_GT(last, 3) << "a 5-degree sun at d = 1 spans several texels of a 2048 map";
  params.set("light.size", 10.0);
  params.set("pcf.match_distance", 10.0);
  r.render(params, request);
  EXPECT_EQ(drawn_pcf_radius(r), FrameLight::kMaxMatchedFilterRadius);
}

TEST_F(MatchedFilterTest, VsmBlurFollowsTheLightsSizeOnlyWhenMatched) {
  const Lab& lab = *find_lab(5);
  Renderer r;
  ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
  r.set_scene(make_default_scene());
  ParamSet params = lab_params(lab);
  const FrameRequest request = small_request(r, params);
  r.render(params, request);
  const long maps = r.stats().shadow_passes;
  params.set("light.size", 3.0);
  r.render(params, request);
  EXPECT_EQ(r.stats().shadow_passes, maps) << "unmatched, light.size is no input of the moments";
  params.set("vsm.match_light", 1.0);
  r.render(params, request);
  EXPECT_EQ(r.stats().shadow_passes, maps + 1) << "matched: the blur width changed";
  const long blurs = r.stats().blur_passes;
  r.render(params, request);
  EXPECT_EQ(r.stats().shadow_passes, maps + 1) << "a still frame redraws nothing";
  params.set("light.size", 5.0);
  r.render(params, request);
  EXPECT_EQ(r.stats().shadow_passes, maps + 2) << "a wider sun, a wider blur";
  EXPECT_EQ(r.stats().blur_passes, blurs + 2);
  params.set("light.size", 0.0);
  r.render(params, request);
  EXPECT_EQ(r.stats().shadow_passes, maps + 3) << "back to the lab's own radius";
}

// Against the exact penumbra of suns 1, 3 and 5 degrees wide on the default scene (2048 map), mean error
// over the penumbra. Measured here:
//   kernel            1 deg    3 deg    5 deg
//   1 x 1             0.240    0.226    0.213
//   5 x 5             0.107    0.118    0.150
//   7 x 7             0.134    0.086    0.126
//   9 x 9             0.161    0.071    0.104
//   matched, d = 1    0.111    0.086    0.084   (radius 1, 3, 5)
// A fixed kernel fits one size; the matched one follows the sun: its worst case over the three (0.111)
// is below every fixed kernel's (the best, 7 x 7, 0.134). None reaches the checks' penumbra limit (0.05):
// one width cannot fit every blocker distance (best matched distance here: 1.5 at 5 degrees, 0.065).
TEST_F(MatchedFilterTest, MatchedPcfFollowsTheSunWhereFixedKernelsFitOneSize) {
  const Lab& lab = *find_lab(6);
  Renderer r;
  ASSERT_TRUE(r.set_features(lab.hooks(Impl::Solution))) << r.shader_error();
  r.set_scene(make_default_scene());
  const Oracle oracle(r.scene());
  ParamSet params = lab_params(lab);
  params.set_from_string("shadow.map_size", "2048");
  params.set("pcf.match_distance", 1.0);
  FrameRequest request = small_request(r, params);
  request.width = 640;
  request.height = 360;
  request.gbuffer = true;
  auto penumbra_error = [&](const char* kernel, bool matched) {
    params.set_from_string("pcf.kernel", kernel);
    params.set("pcf.match_light", matched ? 1.0 : 0.0);
    r.render(params, request);
    const SoftTruth truth = evaluate_soft(oracle, r.read_gbuffer(), oracle_light(r), r.light_size(), kSoftTruthStrata);
    return compare_soft(truth, r.read_visibility()).mae_penumbra;
  };
  double matched_worst = 0.0, best_fixed_worst = 1.0;
  std::string best_fixed;
  std::map<std::string, double> fixed_worst;
  for (double degrees : {1.0, 3.0, 5.0}) {
    params.set("light.size", degrees);
    const double matched = penumbra_error("1", true);
    std::printf("sun %.0f deg: matched (r %d) %.4f;", degrees, drawn_pcf_radius(r), matched);
    matched_worst = std::max(matched_worst, matched);
    for (const char* kernel : {"1", "3", "5", "7", "9"}) {
      const double e = penumbra_error(kernel, false);
      std::printf(" %s: %.4f", kernel, e);
      fixed_worst[kernel] = std::max(fixed_worst[kernel], e);
    }
    std::printf("\n");
  }
  for (const auto& [kernel, worst] : fixed_worst)
    if (worst < best_fixed_worst) best_fixed_worst = worst, best_fixed = kernel;
  std::printf("worst over the three suns: matched %.4f, best fixed kernel (%s) %.4f\n", matched_worst, best_fixed.c_str(),
              best_fixed_worst);
  EXPECT_LT(matched_worst, best_fixed_worst);
  EXPECT_GT(matched_worst, kPenumbraErrorLimit) << "a fixed width was not expected to pass the soft checks";
}

}  // namespace
}  // namespace shadowlab
