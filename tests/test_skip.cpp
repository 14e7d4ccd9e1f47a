// Headless GL tests of what the renderer skips: casters outside the light's volume are not drawn into
// the shadow map (and the map is the same as with every caster drawn), and the counters that show it
// (draws, casters culled, shadow texels written) are exact.
#include <gtest/gtest.h>

#include "renderer/renderer.h"
#include "renderer/technique_params.h"
#include "renderer/vsm_params.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

// A ground, a box under the light and three boxes far to the sides: a narrow spot sees only the first
// two; each face of a point light's cube sees some of them.
Scene spread_scene() {
  Scene s;
  s.meshes.push_back(make_plane({0, 0, 0}, 30.0f, 30.0f, {0.8f, 0.8f, 0.8f}));
  s.meshes.push_back(make_box({0, 1, 0}, {1, 1, 1}, {0.8f, 0.3f, 0.2f}));
  s.meshes.push_back(make_box({25, 1, 0}, {1, 1, 1}, {0.2f, 0.6f, 0.3f}));
  s.meshes.push_back(make_box({-25, 1, 0}, {1, 1, 1}, {0.2f, 0.3f, 0.8f}));
  s.meshes.push_back(make_box({0, 1, 25}, {1, 1, 1}, {0.7f, 0.7f, 0.2f}));
  return s;
}

class SkipTest : public GlTest {
 protected:
  ParamSet params(std::initializer_list<const char*> assignments) {
    ParamSet p(renderer_param_specs());
    for (const auto& spec : technique_param_specs({"light.type", "light.position_x", "light.position_y",
                                                   "light.position_z", "light.cone_deg", "point.single_pass"}))
      p.declare(spec);
    for (const auto& spec : vsm_param_specs({"vsm.blur_radius", "vsm.blur_method"})) p.declare(spec);
    p.apply_assignment("view.debug_quad=false");
    p.apply_assignment("shadow.map_size=512");
    for (const char* a : assignments) p.apply_assignment(a);
    return p;
  }
  FrameRequest request() {
    FrameRequest req;
    req.camera = OrbitCamera::framing(scene.bounds(), 30.0f, 40.0f);
    req.width = 320;
    req.height = 180;
    return req;
  }
  Scene scene = spread_scene();
};

TEST_F(SkipTest, SpotSkipsCastersOutsideItsFrustumAndTheMapIsTheSame) {
  Renderer r;
  r.set_scene(scene);
  LabHooks hooks;
  hooks.light = LightType::Spot;
  ASSERT_TRUE(r.set_lab(hooks)) << r.shader_error();
  // The spot stands 10 above the centre box (the scene's centre is there too), cone 20 degrees.
  const char* spot[] = {"light.position_x=0", "light.position_y=10", "light.position_z=0", "light.cone_deg=20"};
  ParamSet on = params({spot[0], spot[1], spot[2], spot[3], "shadow.cull_casters=true"});
  ParamSet off = params({spot[0], spot[1], spot[2], spot[3], "shadow.cull_casters=false"});
  r.render(off, request());
  const long draws_off = r.stats().draws;
  const long texels_off = r.stats().shadow_texels_written;
  EXPECT_EQ(r.stats().casters_culled, 0);
  int size = 0;
  const std::vector<float> all = r.read_shadow_depth(&size);
  r.render(on, request());
  // The three far boxes are outside the cone: 2 casters drawn instead of 5 (the lit pass draws all 5).
  EXPECT_EQ(r.stats().casters_culled, 3);
  EXPECT_EQ(r.stats().draws - draws_off, 2 + 5);
  EXPECT_EQ(r.stats().shadow_texels_written - texels_off, texels_off) << "the culled boxes wrote no texel";
  const std::vector<float> culled = r.read_shadow_depth(&size);
  ASSERT_EQ(all.size(), culled.size());
  EXPECT_EQ(all, culled) << "culling changed the shadow map";
}

TEST_F(SkipTest, DirectionalFitHoldsEveryCaster) {
  Renderer r;
  r.set_scene(scene);
  r.render(params({"light.elevation=40"}), request());
  EXPECT_EQ(r.stats().casters_culled, 0) << "the fitted ortho box contains the whole scene";
  EXPECT_EQ(r.stats().shadow_passes, 1);
  // Every texel the ground covers is written at least once: the ground fills the map seen from above.
  EXPECT_GE(r.stats().shadow_texels_written, 512L * 512L / 2);
}

TEST_F(SkipTest, PointLightCullsPerCubeFaceAndStoresTheSameDistances) {
  Renderer r;
  r.set_scene(scene);
  LabHooks hooks;
  hooks.light = LightType::Point;
  ASSERT_TRUE(r.set_lab(hooks)) << r.shader_error();
  const char* at = "light.position_y=4";
  r.render(params({at, "point.single_pass=false", "shadow.cull_casters=false"}), request());
  EXPECT_EQ(r.stats().casters_culled, 0);
  const long draws_all = r.stats().draws;
  int size = 0;
  std::vector<float> all[6];
  for (int f = 0; f < 6; ++f) all[f] = r.read_cube_face(f, &size);
  r.render(params({at, "point.single_pass=false", "shadow.cull_casters=true"}), request());
  // 6 faces x 5 casters = 30 candidate draws; the +Y face sees nothing (all below the light), each side
  // face sees at most the ground, the centre box and its own far box.
  const long culled = r.stats().casters_culled;
  EXPECT_GE(culled, 10);
  EXPECT_EQ(r.stats().draws - draws_all, draws_all - culled);
  for (int f = 0; f < 6; ++f) EXPECT_EQ(all[f], r.read_cube_face(f, &size)) << "face " << f;
}

TEST_F(SkipTest, BlurTexelsAndSkippedFramesAreCountedExactly) {
  Renderer r;
  r.set_scene(scene);
  LabHooks hooks;
  hooks.technique = ShadowTechnique::Moments;
  ASSERT_TRUE(r.set_lab(hooks)) << r.shader_error();
  r.render(params({"vsm.blur_radius=0"}), request());
  const long moments_only = r.stats().shadow_texels_written;
  EXPECT_GT(moments_only, 0);
  r.render(params({"vsm.blur_radius=0"}), request());  // nothing changed: no pass, no texel
  EXPECT_EQ(r.stats().shadow_texels_written, moments_only);
  r.render(params({"vsm.blur_radius=2"}), request());
  EXPECT_EQ(r.stats().shadow_texels_written, 2 * moments_only + 2L * 512 * 512) << "moments again plus X and Y";
  const nlohmann::json j = r.stats().to_json();
  EXPECT_EQ(j.at("shadow_texels_written").get<long>(), r.stats().shadow_texels_written);
  EXPECT_EQ(j.at("casters_culled").get<long>(), 0);
}

}  // namespace
}  // namespace shadowlab
