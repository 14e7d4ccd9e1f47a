// Headless GL tests of the flashlight beside the sun (core/flashlight.h): each light has its own map,
// the sun's map is not drawn again while only the flashlight moves (the skip counters), the flashlight's
// shadows agree with the ray-cast oracle cast toward it, and with the flashlight off the picture is the
// one-light picture.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#include "core/flashlight.h"
#include "oracle/oracle.h"
#include "renderer/renderer.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class FlashlightTest : public GlTest {
 protected:
  ParamSet params(std::initializer_list<const char*> assignments) {
    ParamSet p(renderer_param_specs());
    for (const auto& spec : flashlight_param_specs()) p.declare(spec);
    p.apply_assignment("view.debug_quad=false");
    p.apply_assignment("shadow.map_size=1024");
    for (const char* a : assignments) p.apply_assignment(a);
    return p;
  }
  FrameRequest request(float yaw = 30.0f, bool gbuffer = false) {
    FrameRequest req;
    req.camera = OrbitCamera::framing(scene.bounds(), yaw, 40.0f);
    req.width = 320;
    req.height = 180;
    req.gbuffer = gbuffer;
    return req;
  }
  std::unique_ptr<Renderer> renderer(bool flashlight = true) {
    auto r = std::make_unique<Renderer>();
    r->set_scene(scene);
    Features hooks;
    hooks.flashlight = flashlight;
    EXPECT_TRUE(r->set_features(hooks)) << r->shader_error();
    return r;
  }
  Scene scene = make_default_scene();
};

TEST_F(FlashlightTest, MovingTheFlashlightDoesNotRedrawTheSunsMap) {
  auto r = renderer();
  r->render(params({"flashlight.phase=200"}), request());
  ASSERT_EQ(r->stats().shadow_passes, 1);
  ASSERT_EQ(r->stats().flashlight_shadow_passes, 1);
  int size = 0;
  const std::vector<float> sun_before = r->read_shadow_depth(&size);
  const std::vector<float> flash_before = r->read_flashlight_depth(&size);
  r->render(params({"flashlight.phase=200"}), request());
  EXPECT_EQ(r->stats().shadow_passes, 1) << "a still frame";
  EXPECT_EQ(r->stats().flashlight_shadow_passes, 1) << "a still frame";
  // The node moves along its circle, as the window animates it: ten frames, ten flashlight maps, one sun map.
  for (int i = 1; i <= 10; ++i) {
    const std::string phase = "flashlight.phase=" + std::to_string(200 + 7 * i);
    ParamSet p = params({});
    p.apply_assignment(phase);
    r->render(p, request());
  }
  EXPECT_EQ(r->stats().shadow_passes, 1) << "the sun's map was drawn again while only the flashlight moved";
  EXPECT_EQ(r->stats().flashlight_shadow_passes, 11);
  EXPECT_EQ(r->read_shadow_depth(&size), sun_before);
  EXPECT_NE(r->read_flashlight_depth(&size), flash_before) << "the flashlight's map did not follow it";
  // The flashlight's own parameters (intensity) redraw neither map; the sun moving redraws only the sun's.
  r->render(params({"flashlight.phase=270", "flashlight.intensity=0.5"}), request());
  EXPECT_EQ(r->stats().shadow_passes, 1);
  EXPECT_EQ(r->stats().flashlight_shadow_passes, 11);
  r->render(params({"flashlight.phase=270", "flashlight.intensity=0.5", "light.azimuth=80"}), request());
  EXPECT_EQ(r->stats().shadow_passes, 2);
  EXPECT_EQ(r->stats().flashlight_shadow_passes, 11);
}

TEST_F(FlashlightTest, OnTheCameraItFollowsTheCameraAndTheSunStays) {
  auto r = renderer();
  for (int i = 0; i < 5; ++i) r->render(params({"flashlight.mount=camera"}), request(30.0f + 10.0f * static_cast<float>(i)));
  EXPECT_EQ(r->stats().shadow_passes, 1);
  EXPECT_EQ(r->stats().flashlight_shadow_passes, 5);
  const FrameLight* f = r->flashlight();
  ASSERT_NE(f, nullptr);
  const glm::vec3 eye = request(70.0f).camera.eye();
  EXPECT_LT(glm::distance(f->scene_position, eye), 0.2f * glm::length(scene.bounds().extent()));
  const glm::vec3 forward = glm::normalize(request(70.0f).camera.target - eye);
  EXPECT_GT(glm::dot(f->spot_direction, forward), 0.999f);
}

TEST_F(FlashlightTest, WithTheFlashlightOffThePictureIsTheSunsAlone) {
  auto one = renderer(false);
  auto two = renderer(true);
  one->render(params({}), request());
  two->render(params({"flashlight.intensity=0"}), request());
  const auto a = one->read_color(), b = two->read_color();
  ASSERT_EQ(a.size(), b.size());
  int worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
  EXPECT_LE(worst, 1) << "the two-light program with the flashlight at 0 differs from the one-light program";
  // ... and with the flashlight on, it adds light.
  two->render(params({}), request());
  const auto c = two->read_color();
  long brighter = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) brighter += int(c[i]) > int(a[i]) + 4;
  EXPECT_GT(brighter, 1000);
}

// The flashlight alone (sun.intensity 0): a pixel is lit where it is brighter than the ambient-only
// picture. Against the oracle cast toward the flashlight, on the interior pixels of its cone.
TEST_F(FlashlightTest, ItsShadowsAgreeWithTheOracle) {
  auto r = renderer();
  const FrameRequest req = request(30.0f, true);
  r->render(params({"sun.intensity=0", "flashlight.intensity=0"}), req);
  const auto ambient = r->read_color();
  r->render(params({"sun.intensity=0"}), req);
  const auto lit = r->read_color();
  const GBuffer g = r->read_gbuffer();
  const FrameLight f = *r->flashlight();
  int size = 0;
  r->read_flashlight_depth(&size);
  OracleLight light;
  light.positional = true;
  light.position = f.scene_position;
  light.texel_angle = f.texel_angle(size);
  const Oracle oracle(r->scene());
  const Truth truth = oracle.evaluate(g, light, BandSpec{});
  long graded = 0, agree = 0, shadowed = 0;
  const float cos_cone = std::cos(glm::radians(f.spot_cone_deg - 1.0f));
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const int i = y * g.width + x;
      if (!truth.valid[i] || !truth.interior[i]) continue;
      const glm::vec3 p = g.position[i];
      const glm::vec3 to_light = glm::normalize(f.scene_position - p);
      if (glm::dot(-to_light, f.spot_direction) < cos_cone || glm::dot(g.normal[i], to_light) < 0.1f) continue;
      const int top = (g.height - 1 - y) * g.width + x;  // colour is top row first
      const bool drawn_lit = int(lit[4 * top]) > int(ambient[4 * top]) + 2;
      ++graded;
      shadowed += !truth.lit[i];
      agree += drawn_lit == (truth.lit[i] != 0);
    }
  ASSERT_GT(graded, 2000);
  ASSERT_GT(shadowed, 200) << "the flashlight casts no shadow to grade";
  EXPECT_GE(static_cast<double>(agree) / static_cast<double>(graded), 0.995)
      << agree << " of " << graded << " pixels agree (" << shadowed << " truly shadowed)";
}

TEST_F(FlashlightTest, AnimationAdvancesThePhaseAndWraps) {
  ParamSet p = params({"flashlight.phase=350", "flashlight.speed=30"});
  EXPECT_NEAR(advance_flashlight_phase(p, 1.0), 20.0, 1e-9);
  p.apply_assignment("flashlight.speed=-30");
  p.apply_assignment("flashlight.phase=10");
  EXPECT_NEAR(advance_flashlight_phase(p, 1.0), 340.0, 1e-9);
}

}  // namespace
}  // namespace shadowlab
