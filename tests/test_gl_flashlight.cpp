// Headless GL tests of the flashlight beside the sun (core/flashlight.h): each light has its own map,
// the sun's map is not drawn again while only the flashlight moves (the skip counters), the flashlight's
// shadows agree with the ray-cast oracle cast toward it, and with the flashlight off the picture is the
// one-light picture. The flashlight is one entry of Features::lights (renderer/shadowed_light.h): a third
// light is one more entry, and its shadows agree with the oracle too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
  std::unique_ptr<Renderer> renderer(bool flashlight = true, std::vector<ShadowedLightSpec> more = {}) {
    auto r = std::make_unique<Renderer>();
    r->set_scene(scene);
    Features hooks;
    if (flashlight) hooks.lights.push_back(flashlight_spec());
    for (ShadowedLightSpec& spec : more) hooks.lights.push_back(std::move(spec));
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
  const std::vector<float> flash_before = r->shadowed_light("flashlight").read_depth(&size);
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
  EXPECT_NE(r->shadowed_light("flashlight").read_depth(&size), flash_before) << "the flashlight's map did not follow it";
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
  ASSERT_EQ(r->shadowed_lights().size(), 1u);
  const FrameLight* f = &r->shadowed_light("flashlight").light();
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

// One shadowed light alone (the others at 0 in `alone`): a pixel is lit where it is brighter than the
// ambient-only picture (`ambient`: every light at 0). Against the oracle cast toward that light, on the
// interior pixels of its cone. Returns the shadowed pixels graded.
long expect_agrees_with_oracle(const Renderer& r, const ShadowedLight& light, const std::vector<std::uint8_t>& ambient,
                               const std::vector<std::uint8_t>& alone, const GBuffer& g) {
  const FrameLight f = light.light();
  int size = 0;
  light.read_depth(&size);
  OracleLight oracle_light;
  oracle_light.positional = true;
  oracle_light.position = f.scene_position;
  oracle_light.texel_angle = f.texel_angle(size);
  const Oracle oracle(r.scene());
  const Truth truth = oracle.evaluate(g, oracle_light, BandSpec{});
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
      const bool drawn_lit = int(alone[4 * top]) > int(ambient[4 * top]) + 2;
      ++graded;
      shadowed += !truth.lit[i];
      agree += drawn_lit == (truth.lit[i] != 0);
    }
  std::printf("%s alone against the oracle: %ld of %ld graded pixels agree, %ld truly shadowed\n", light.name().c_str(),
              agree, graded, shadowed);
  EXPECT_GT(graded, 2000) << light.name();
  EXPECT_GE(static_cast<double>(agree) / static_cast<double>(std::max(graded, 1L)), 0.995)
      << light.name() << ": " << agree << " of " << graded << " pixels agree (" << shadowed << " truly shadowed)";
  return shadowed;
}

// The flashlight alone (sun.intensity 0).
TEST_F(FlashlightTest, ItsShadowsAgreeWithTheOracle) {
  auto r = renderer();
  const FrameRequest req = request(30.0f, true);
  r->render(params({"sun.intensity=0", "flashlight.intensity=0"}), req);
  const auto ambient = r->read_color();
  r->render(params({"sun.intensity=0"}), req);
  const auto lit = r->read_color();
  EXPECT_GT(expect_agrees_with_oracle(*r, r->shadowed_light("flashlight"), ambient, lit, r->read_gbuffer()), 200)
      << "the flashlight casts no shadow to grade";
}

TEST_F(FlashlightTest, AnimationAdvancesThePhaseAndWraps) {
  ParamSet p = params({"flashlight.phase=350", "flashlight.speed=30"});
  EXPECT_NEAR(advance_flashlight_phase(p, 1.0), 20.0, 1e-9);
  p.apply_assignment("flashlight.speed=-30");
  p.apply_assignment("flashlight.phase=10");
  EXPECT_NEAR(advance_flashlight_phase(p, 1.0), 340.0, 1e-9);
}


// A third light: a second spot (the flashlight's node on the other side of its circle, phase 20 against
// 200, intensity 0.8 whatever flashlight.intensity says) added as one more Features::lights entry, no
// renderer member of its own. Each entry draws its own map once; the torch alone casts the shadows the
// oracle cast toward it finds; beside the sun and the flashlight it only adds light (the default
// combination, a sum), and its map is in the corner under its own name.
class ShadowedLightTest : public FlashlightTest {
 protected:
  static ShadowedLightSpec torch() {
    ShadowedLightSpec spec = flashlight_spec();
    spec.name = "torch";
    spec.pass_name = "torch shadow";
    spec.place = [](const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view) {
      ParamSet p = params;
      p.set("flashlight.phase", 20.0);
      return flashlight_light(p, bounds, camera_view);
    };
    spec.intensity = [](const ParamSet&) { return 0.8f; };
    return spec;
  }
};

TEST_F(ShadowedLightTest, AThirdLightIsOneMoreEntry) {
  auto two = renderer();
  auto three = renderer(true, {torch()});
  ASSERT_EQ(three->shadowed_lights().size(), 2u);
  const FrameRequest req = request(30.0f, true);
  two->render(params({}), req);
  three->render(params({}), req);
  const ShadowedLight& torch_light = three->shadowed_light("torch");
  const ShadowedLight& flashlight = three->shadowed_light("flashlight");
  EXPECT_EQ(three->stats().shadow_passes, 1);
  EXPECT_EQ(three->stats().flashlight_shadow_passes, 2) << "each entry draws its own map";
  EXPECT_EQ(torch_light.map_updates(), 1);
  EXPECT_EQ(flashlight.map_updates(), 1);
  int size = 0;
  EXPECT_NE(torch_light.read_depth(&size), flashlight.read_depth(&size)) << "the torch's map is the flashlight's";
  EXPECT_GT(glm::distance(torch_light.light().scene_position, flashlight.light().scene_position),
            0.5f * glm::length(scene.bounds().extent()));
  // Beside the sun and the flashlight the torch only adds light.
  const auto a = two->read_color(), b = three->read_color();
  ASSERT_EQ(a.size(), b.size());
  long brighter = 0, darker = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) {
    brighter += int(b[i]) > int(a[i]) + 4;
    darker += int(b[i]) + 1 < int(a[i]);
  }
  EXPECT_GT(brighter, 1000);
  EXPECT_EQ(darker, 0);
  // The torch alone against the oracle cast toward it; the ambient picture from the two-light renderer.
  two->render(params({"sun.intensity=0", "flashlight.intensity=0"}), req);
  const auto ambient = two->read_color();
  three->render(params({"sun.intensity=0", "flashlight.intensity=0"}), req);
  EXPECT_GT(expect_agrees_with_oracle(*three, torch_light, ambient, three->read_color(), three->read_gbuffer()), 200)
      << "the torch casts no shadow to grade";
  // Its map in the corner, left of the flashlight's, under its own name.
  three->render(params({"view.debug_quad=true"}), req);
  std::vector<std::string> labels;
  for (const DebugQuadLabel& q : three->annotations().quads) labels.push_back(q.text);
  const std::vector<std::string> expected = {"sun: shadow map depth (light's view)",
                                             "flashlight: shadow map depth (light's view)",
                                             "torch: shadow map depth (light's view)"};
  EXPECT_EQ(labels, expected);
}

// The most the lit pass takes (its whole unrolled loop) builds and draws, each entry's map once; one more
// is refused and the features before stay.
TEST_F(ShadowedLightTest, MoreLightsThanTheLitPassTakesAreRefused) {
  auto r = std::make_unique<Renderer>();
  r->set_scene(scene);
  Features hooks;
  hooks.lights.assign(kMaxShadowedLights, torch());
  ASSERT_TRUE(r->set_features(hooks)) << r->shader_error();
  r->render(params({}), request());
  EXPECT_EQ(r->stats().flashlight_shadow_passes, kMaxShadowedLights);
  hooks.lights.push_back(torch());
  EXPECT_FALSE(r->set_features(hooks));
  EXPECT_NE(r->shader_error().find("at most 4"), std::string::npos) << r->shader_error();
  EXPECT_EQ(r->shadowed_lights().size(), static_cast<std::size_t>(kMaxShadowedLights));
}

}  // namespace
}  // namespace shadowlab
