// Headless GL tests of what the renderer skips: casters outside the light's volume are not drawn into
// the shadow map (and the map is the same as with every caster drawn), and the counters that show it
// (draws, casters culled, shadow texels written) are exact.
#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include "renderer/renderer.h"
#include "core/technique_params.h"
#include "core/vsm_params.h"
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
  // A renderer on the spread scene with a lab's hooks: a light type, a technique.
  std::unique_ptr<Renderer> renderer(std::optional<LightType> light = {},
                                     ShadowTechnique technique = ShadowTechnique::Depth) {
    auto r = std::make_unique<Renderer>();
    r->set_scene(scene);
    Features hooks;
    hooks.light = light;
    hooks.technique = technique;
    EXPECT_TRUE(r->set_features(hooks)) << r->shader_error();
    return r;
  }
  Scene scene = spread_scene();
};

TEST_F(SkipTest, SpotSkipsCastersOutsideItsFrustumAndTheMapIsTheSame) {
  auto r = renderer(LightType::Spot);
  // The spot stands 10 above the centre box (the scene's centre is there too), cone 20 degrees.
  const char* spot[] = {"light.position_x=0", "light.position_y=10", "light.position_z=0", "light.cone_deg=20"};
  ParamSet on = params({spot[0], spot[1], spot[2], spot[3], "shadow.cull_casters=true"});
  ParamSet off = params({spot[0], spot[1], spot[2], spot[3], "shadow.cull_casters=false"});
  r->render(off, request());
  const long draws_off = r->stats().draws;
  const long texels_off = r->stats().shadow_texels_written;
  EXPECT_EQ(r->stats().casters_culled, 0);
  int size = 0;
  const std::vector<float> all = r->read_shadow_depth(&size);
  r->render(on, request());
  // The three far boxes are outside the cone: 2 casters drawn instead of 5 (the lit pass draws all 5).
  EXPECT_EQ(r->stats().casters_culled, 3);
  EXPECT_EQ(r->stats().draws - draws_off, 2 + 5);
  EXPECT_EQ(r->stats().shadow_texels_written - texels_off, texels_off) << "the culled boxes wrote no texel";
  const std::vector<float> culled = r->read_shadow_depth(&size);
  ASSERT_EQ(all.size(), culled.size());
  EXPECT_EQ(all, culled) << "culling changed the shadow map";
}

TEST_F(SkipTest, DirectionalFitHoldsEveryCaster) {
  auto r = renderer();
  r->render(params({"light.elevation=40"}), request());
  EXPECT_EQ(r->stats().casters_culled, 0) << "the fitted ortho box contains the whole scene";
  EXPECT_EQ(r->stats().shadow_passes, 1);
  // Every texel the ground covers is written at least once: the ground fills the map seen from above.
  EXPECT_GE(r->stats().shadow_texels_written, 512L * 512L / 2);
}

TEST_F(SkipTest, PointLightCullsPerCubeFaceAndStoresTheSameDistances) {
  auto r = renderer(LightType::Point);
  const char* at = "light.position_y=4";
  r->render(params({at, "point.single_pass=false", "shadow.cull_casters=false"}), request());
  EXPECT_EQ(r->stats().casters_culled, 0);
  const long draws_all = r->stats().draws;
  int size = 0;
  std::vector<float> all[6];
  for (int f = 0; f < 6; ++f) all[f] = r->read_cube_face(f, &size);
  r->render(params({at, "point.single_pass=false", "shadow.cull_casters=true"}), request());
  // 6 faces x 5 casters = 30 candidate draws; the +Y face sees nothing (all below the light), each side
  // face sees at most the ground, the centre box and its own far box.
  const long culled = r->stats().casters_culled;
  EXPECT_GE(culled, 10);
  EXPECT_EQ(r->stats().draws - draws_all, draws_all - culled);
  for (int f = 0; f < 6; ++f) EXPECT_EQ(all[f], r->read_cube_face(f, &size)) << "face " << f;
}

TEST_F(SkipTest, BlurTexelsAndSkippedFramesAreCountedExactly) {
  auto r = renderer({}, ShadowTechnique::Moments);
  r->render(params({"vsm.blur_radius=0"}), request());
  const long moments_only = r->stats().shadow_texels_written;
  EXPECT_GT(moments_only, 0);
  r->render(params({"vsm.blur_radius=0"}), request());  // nothing changed: no pass, no texel
  EXPECT_EQ(r->stats().shadow_texels_written, moments_only);
  r->render(params({"vsm.blur_radius=2"}), request());
  EXPECT_EQ(r->stats().shadow_texels_written, 2 * moments_only + 2L * 512 * 512) << "moments again plus X and Y";
  const nlohmann::json j = r->stats().to_json();
  EXPECT_EQ(j.at("shadow_texels_written").get<long>(), r->stats().shadow_texels_written);
  EXPECT_EQ(j.at("casters_culled").get<long>(), 0);
}

// Share of pixels that differ between two RGBA8 frames inside a rectangle (x0, y0)-(x1, y1), top-left
// origin.
double differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int width, int x0, int y0,
                 int x1, int y1) {
  long diff = 0, total = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
      ++total;
      if (a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2]) ++diff;
    }
  return total ? static_cast<double>(diff) / static_cast<double>(total) : 0.0;
}

bool has_pass(const FrameStats& stats, const std::string& name) {
  for (const auto& p : stats.passes)
    if (p.name == name) return true;
  return false;
}

TEST_F(SkipTest, LightVolumeWireframeDrawsOnlyWhenShown) {
  auto r = renderer();
  const FrameRequest req = request();
  r->render(params({"view.light_volume=false"}), req);
  EXPECT_FALSE(has_pass(r->stats(), "light_volume_view"));
  const auto off = r->read_color();
  r->render(params({"view.light_volume=true"}), req);
  EXPECT_TRUE(has_pass(r->stats(), "light_volume_view"));
  const auto on = r->read_color();
  // The box's edges in the wireframe's colour (255, 217, 51), and only lines: a few percent of the frame.
  long yellow = 0;
  for (std::size_t i = 0; i < on.size(); i += 4)
    if (on[i] > 240 && on[i + 1] > 200 && on[i + 1] < 235 && on[i + 2] < 70) ++yellow;
  EXPECT_GT(yellow, 200);
  const double changed = differing(on, off, req.width, 0, 0, req.width, req.height);
  EXPECT_GT(changed, 0.003);
  EXPECT_LT(changed, 0.1);
  // A spot light's frustum too; a point light has nothing to draw (no pass).
  Features spot;
  spot.light = LightType::Spot;
  ASSERT_TRUE(r->set_features(spot));
  r->render(params({"view.light_volume=true", "light.position_y=10", "light.cone_deg=20"}), req);
  EXPECT_TRUE(has_pass(r->stats(), "light_volume_view"));
  Features point;
  point.light = LightType::Point;
  ASSERT_TRUE(r->set_features(point));
  r->render(params({"view.light_volume=true", "light.position_y=4"}), req);
  EXPECT_FALSE(has_pass(r->stats(), "light_volume_view"));
}

TEST_F(SkipTest, DebugQuadsGrowAndShowTheChosenChannel) {
  auto r = renderer();
  FrameRequest req = request();
  r->render(params({"view.debug_quad=false"}), req);
  EXPECT_FALSE(has_pass(r->stats(), "debug_quad"));
  const auto none = r->read_color();
  const int w = req.width, h = req.height;
  auto covered = [&](const std::vector<std::uint8_t>& img) { return differing(img, none, w, 0, 0, w, h); };
  r->render(params({"view.debug_quad=true", "view.debug_quad_size=0.25"}), req);
  const double small = covered(r->read_color());
  r->render(params({"view.debug_quad=true", "view.debug_quad_size=0.75"}), req);
  const double large = covered(r->read_color());
  // The quad's area grows with the square of its side: (0.75 / 0.25)^2 = 9.
  EXPECT_GT(large, 6.0 * small);
  EXPECT_GT(small, 0.01);

  // Moments: "all" draws E[z], E[z^2] and the variance side by side; one channel draws one quad, and the
  // three channels differ.
  Features vsm;
  vsm.technique = ShadowTechnique::Moments;
  ASSERT_TRUE(r->set_features(vsm));
  r->render(params({"view.debug_quad=false"}), req);
  const auto vsm_none = r->read_color();
  auto vsm_covered = [&](const std::vector<std::uint8_t>& img) { return differing(img, vsm_none, w, 0, 0, w, h); };
  r->render(params({"view.debug_quad=true", "view.debug_channel=all"}), req);
  const double three = vsm_covered(r->read_color());
  std::vector<std::uint8_t> channel[3];
  const char* names[] = {"view.debug_channel=moment 1", "view.debug_channel=moment 2", "view.debug_channel=variance"};
  for (int c = 0; c < 3; ++c) {
    r->render(params({"view.debug_quad=true", names[c]}), req);
    channel[c] = r->read_color();
  }
  const double one = vsm_covered(channel[0]);
  EXPECT_NEAR(three / one, 3.0, 0.3);
  const int side = h / 4;  // the single quad, bottom right
  const int x0 = w - side - 8, y0 = h - 8 - side;
  EXPECT_GT(differing(channel[0], channel[2], w, x0, y0, x0 + side, y0 + side), 0.2) << "variance looks like E[z]";
  EXPECT_GT(differing(channel[0], channel[1], w, x0, y0, x0 + side, y0 + side), 0.2) << "E[z^2] looks like E[z]";

  // A point light's six cube faces, in the window as in the PNG.
  Features point;
  point.light = LightType::Point;
  ASSERT_TRUE(r->set_features(point));
  r->render(params({"view.debug_quad=false", "light.position_y=4"}), req);
  const auto point_none = r->read_color();
  r->render(params({"view.debug_quad=true", "light.position_y=4"}), req);
  EXPECT_TRUE(has_pass(r->stats(), "debug_quad"));
  EXPECT_GT(differing(r->read_color(), point_none, w, 0, 0, w, h), 0.01);
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// The techniques that keep a shadow map, each with what its map holds as floats (depths; a point
// light's six distance faces; the moments and their depth buffer).
struct MapTechnique {
  const char* name;
  std::optional<LightType> light;
  ShadowTechnique technique;
  std::vector<const char*> assignments;
};

const MapTechnique kMapTechniques[] = {
    {"directional depth map", {}, ShadowTechnique::Depth, {}},
    {"spot depth map", LightType::Spot, ShadowTechnique::Depth, {"light.position_y=10", "light.cone_deg=30"}},
    {"point cube map", LightType::Point, ShadowTechnique::Depth, {"light.position_y=4"}},
    {"moments, blurred", {}, ShadowTechnique::Moments, {"vsm.blur_radius=2"}},
};

std::vector<float> map_contents(const Renderer& r, const MapTechnique& t) {
  int size = 0;
  std::vector<float> out = r.read_shadow_depth(&size);
  if (t.technique == ShadowTechnique::Moments) {
    const std::vector<float> moments = r.read_moments(&size);
    out.insert(out.end(), moments.begin(), moments.end());
  }
  if (t.light == LightType::Point) {
    for (int f = 0; f < 6; ++f) {
      const std::vector<float> face = r.read_cube_face(f, &size);
      out.insert(out.end(), face.begin(), face.end());
    }
  }
  return out;
}

// Every parameter the renderer declares, in every group.
std::vector<ParamSpec> every_spec() {
  std::vector<ParamSpec> all = renderer_param_specs();
  for (auto group : {vsm_param_specs(), light_param_specs(), pcf_param_specs(), point_param_specs(), volume_param_specs()})
    all.insert(all.end(), group.begin(), group.end());
  return all;
}

// A valid value other than `current`.
double other_value(const ParamSpec& s, double current) {
  switch (s.kind) {
    case ParamKind::Bool: return current != 0.0 ? 0.0 : 1.0;
    case ParamKind::Choice: return current + 1.0 < static_cast<double>(s.choices.size()) ? current + 1.0 : 0.0;
    default: return current != s.max ? s.max : s.min;
  }
}

class InvalidationTest : public SkipTest {
 protected:
  ParamSet every_param(const MapTechnique& t) {
    ParamSet p(every_spec());
    p.apply_assignment("view.debug_quad=false");
    p.apply_assignment("shadow.map_size=256");
    for (const char* a : t.assignments) p.apply_assignment(a);
    return p;
  }
};

// A parameter the renderer has never heard of redraws the map just by declaring kInvalidatesShadowMap;
// one without the bit does not, whatever the technique.
TEST_F(InvalidationTest, ADeclaredShadowMapBitRedrawsTheMapAndNothingElseDoes) {
  for (const MapTechnique& t : kMapTechniques) {
    SCOPED_TRACE(t.name);
    auto r = renderer(t.light, t.technique);
    ParamSet p = every_param(t);
    p.declare({"test.map_input", "Something the shadow pass reads", ParamKind::Float, 1.0, 0.0, 2.0, "", {},
               kInvalidatesShadowMap});
    p.declare({"test.view_input", "Something only the lit pass reads", ParamKind::Float, 1.0, 0.0, 2.0, "", {}});
    r->render(p, request());
    ASSERT_EQ(r->stats().shadow_passes, 1);
    r->render(p, request());
    EXPECT_EQ(r->stats().shadow_passes, 1) << "nothing changed";
    p.set("test.view_input", 1.5);
    r->render(p, request());
    EXPECT_EQ(r->stats().shadow_passes, 1) << "a parameter without the bit changed";
    p.set("test.map_input", 1.5);
    r->render(p, request());
    EXPECT_EQ(r->stats().shadow_passes, 2) << "a parameter with the bit changed";
    r->render(p, request());
    EXPECT_EQ(r->stats().shadow_passes, 2);
  }
}

// The audit of the declarations: every parameter that does not declare kInvalidatesShadowMap leaves
// every technique's map exactly as it was (so skipping the map on its change can never show a stale
// one). Each is set to another value and the map drawn again by force.
TEST_F(InvalidationTest, NoParameterWithoutTheBitChangesAnyMap) {
  for (const MapTechnique& t : kMapTechniques) {
    SCOPED_TRACE(t.name);
    auto r = renderer(t.light, t.technique);
    const ParamSet base = every_param(t);
    r->render(base, request());
    const std::vector<float> reference = map_contents(*r, t);
    ASSERT_FALSE(reference.empty());
    int checked = 0;
    for (const ParamSpec& spec : base.specs()) {
      if (spec.invalidates & kInvalidatesShadowMap) continue;
      ParamSet changed = base;
      changed.set(spec.key, other_value(spec, base.get(spec.key)));
      r->invalidate_shadow_map();
      r->render(changed, request());
      EXPECT_EQ(map_contents(*r, t), reference) << spec.key << "=" << changed.format(spec.key)
                                                << " changed the map: it must declare kInvalidatesShadowMap";
      ++checked;
    }
    EXPECT_GE(checked, 15);
  }
}

}  // namespace
}  // namespace shadowlab
