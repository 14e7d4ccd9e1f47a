// The SSAO pass (renderer/ssao_pass.h, lab 17): its kernel and noise, that it exists only when the features
// switch it on, and what it draws on the default scene with the solution and with the stock exercise.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "core/technique_params.h"
#include "renderer/renderer.h"
#include "renderer/ssao_pass.h"
#include "tests/gl_fixture.h"

namespace shadowlab {

TEST(SsaoKernel, SamplesLieInTheUnitHemisphereAroundZ) {
  for (const glm::vec3& s : ssao_kernel()) {
    EXPECT_GE(s.z, 0.0f);
    EXPECT_LE(glm::dot(s, s), 1.0f);
    EXPECT_GT(glm::dot(s, s), 0.0f);
  }
}

TEST(SsaoKernel, NoiseLiesInTheScreenPlane) {
  for (const glm::vec3& v : ssao_noise()) {
    EXPECT_EQ(v.z, 0.0f);
    EXPECT_LE(std::max(std::abs(v.x), std::abs(v.y)), 1.0f);
  }
}

class SsaoTest : public GlTest {
 protected:
  // The default scene from above and aside: boxes standing on the open floor, their feet in view.
  const FrameStats& render(Renderer& r, const Features& features, bool blur = true) {
    EXPECT_TRUE(r.set_features(features)) << r.shader_error();
    r.set_scene(make_default_scene());
    params.set(param::view_debug_quad, false);
    params.set(param::ssao_blur, blur);
    FrameRequest req;
    req.camera = OrbitCamera::framing(make_default_scene().bounds(), 30.0f, 35.0f);
    req.width = 320;
    req.height = 180;
    return r.render(params, req);
  }
  static bool has_pass(const FrameStats& stats, std::string_view name) {
    return std::any_of(stats.passes.begin(), stats.passes.end(), [&](const PassTiming& p) { return p.name == name; });
  }
  ParamSet params = with_ssao_specs();
  static ParamSet with_ssao_specs() {
    ParamSet p{renderer_param_specs()};
    for (const ParamSpec& spec : ssao_param_specs()) p.declare(spec);
    return p;
  }
};

TEST_F(SsaoTest, NoPassAndNoReadBackWithoutTheFeature) {
  Renderer r;
  const FrameStats& stats = render(r, Features{});
  EXPECT_FALSE(has_pass(stats, "ssao"));
  EXPECT_FALSE(has_pass(stats, "ssao_gbuffer"));
  EXPECT_THROW(r.read_ao(), std::logic_error);
}

TEST_F(SsaoTest, SolutionOpensTheFloorAndDarkensTheCreases) {
  Renderer r;
  Features f;
  f.ssao = true;  // the default include: the solution, shaders/ssao/ssao_core.glsl
  for (bool blur : {false, true}) {
    const FrameStats& stats = render(r, f, blur);
    EXPECT_TRUE(has_pass(stats, "ssao"));
    EXPECT_EQ(has_pass(stats, "ssao_blur"), blur);
    const std::vector<float> ao = r.read_ao(blur);
    ASSERT_EQ(ao.size(), 320u * 180u);
    long open = 0, dark = 0;
    for (float v : ao) {
      EXPECT_GE(v, 0.0f);
      EXPECT_LE(v, 1.0f);
      open += v > 0.99f;
      dark += v < 0.9f;
    }
    // Most of the frame is open floor or background; the boxes' feet and the sphere's contact are darker
    // (measured at this size: the darkest pixel 0.54 raw, 0.80 blurred; the stock exercise's is 1).
    EXPECT_GT(open, static_cast<long>(ao.size()) / 2) << "blur " << blur;
    EXPECT_GT(dark, 0) << "blur " << blur;
  }
}

TEST_F(SsaoTest, StockExerciseIsOpenEverywhere) {
  Renderer r;
  Features f;
  f.ssao = true;
  f.includes["lab/ssao.glsl"] = "labs/17_ssao/exercise.glsl";
  render(r, f);
  const std::vector<float> ao = r.read_ao();
  ASSERT_FALSE(ao.empty());
  EXPECT_EQ(*std::min_element(ao.begin(), ao.end()), 1.0f);
}

}  // namespace shadowlab
