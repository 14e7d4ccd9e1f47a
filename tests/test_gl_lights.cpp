// Headless GL tests of the light types and techniques of labs 6-9: the cube shadow map (six passes
// and one layered pass agree; a point light among the objects shadows every side), stencil shadow
// volumes (the camera inside a volume: z-fail right, z-pass wrong; the adjacency report names open
// edges), targets allocated only when used, and the geometry-shader debug views.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>

#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/gl_objects.h"
#include "oracle/metrics.h"
#include "renderer/renderer.h"
#include "renderer/shadow_volume_pass.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class LightsTest : public GlTest {
 protected:
  FrameRequest request(const OrbitCamera& camera, int w = 320, int h = 180) {
    FrameRequest req;
    req.camera = camera;
    req.width = w;
    req.height = h;
    req.gbuffer = true;
    return req;
  }
  ParamSet lab_set(std::initializer_list<const char*> assignments) {
    ParamSet p(renderer_param_specs());
    for (const auto& spec : technique_param_specs({"light.type", "light.position_x", "light.position_y",
                                                   "light.position_z", "light.cone_deg", "volume.method",
                                                   "point.single_pass", "pcf.kernel", "pcf.hardware"}))
      p.declare(spec);
    p.apply_assignment("view.debug_quad=false");
    for (const char* a : assignments) p.apply_assignment(a);
    return p;
  }
  // Agreement with the oracle over interior pixels of the renderer's last frame. Shadow volumes have no
  // texels: their band is 1 screen pixel; shadow maps use the oracle's band of 2 texels.
  double agreement(Renderer& r, const Oracle& oracle, bool screen_band = true) {
    BandSpec band;
    band.fixed_screen_pixels = screen_band ? 1 : 0;
    const Truth t = oracle.evaluate(r.read_gbuffer(), oracle_light(r), band);
    return interior_agreement(compare(t, r.read_visibility()));
  }
  Scene scene = make_default_scene();
};

TEST_F(LightsTest, ZFailStaysRightInsideAVolumeWhereZPassFails) {
  Renderer r;
  r.set_scene(scene);
  Features hooks;
  hooks.technique = ShadowTechnique::ShadowVolumes;
  ASSERT_TRUE(r.set_features(hooks)) << r.shader_error();
  const Oracle oracle(scene);
  // The eye 0.3 above the ground in the big box's shadow (light at azimuth 35, elevation 50).
  const glm::vec3 eye(-3.67f, 0.3f, -0.68f);
  const glm::vec3 to_light = direction_from_angles(35.0f, 50.0f);
  ASSERT_TRUE(oracle.occluded(eye, to_light, std::numeric_limits<float>::infinity()));
  const OrbitCamera inside = camera_looking_at(eye, {-3.5f, 0.0f, 4.0f}, 0.05f, 100.0f);
  r.render(lab_set({"volume.method=z-fail"}), request(inside));
  EXPECT_GE(agreement(r, oracle), 0.995);
  r.render(lab_set({"volume.method=z-pass"}), request(inside));
  EXPECT_LT(agreement(r, oracle), 0.5) << "z-pass counts the volume the eye is in once too few";
  // From outside every volume both methods agree with the truth.
  const OrbitCamera outside = OrbitCamera::framing(scene.bounds());
  for (const char* method : {"volume.method=z-fail", "volume.method=z-pass"}) {
    r.render(lab_set({method}), request(outside));
    EXPECT_GE(agreement(r, oracle), 0.995) << method;
  }
  EXPECT_EQ(r.stats().stencil_passes, 4);
  EXPECT_EQ(r.stats().shadow_passes, 0) << "shadow volumes need no shadow map";
}

TEST_F(LightsTest, AdjacencyReportNamesOpenEdges) {
  Scene s = scene;
  Mesh open_box = make_box({3.5f, 0.5f, -3.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f});
  open_box.name = "open box";
  open_box.indices.resize(open_box.indices.size() - 6);  // drop the last face: a hole with 4 open edges
  s.meshes.push_back(open_box);
  Renderer r;
  r.set_scene(s);
  Features hooks;
  hooks.technique = ShadowTechnique::ShadowVolumes;
  ASSERT_TRUE(r.set_features(hooks)) << r.shader_error();
  r.render(lab_set({}), request(OrbitCamera::framing(s.bounds())));
  bool saw_ground = false, saw_open_box = false;
  for (const auto& m : r.volume_report()) {
    if (m.name == "ground") {
      saw_ground = true;
      EXPECT_EQ(m.open_edges, 4u);  // a single-sided plane is open all round
    } else if (m.name == "open box") {
      saw_open_box = true;
      EXPECT_EQ(m.open_edges, 4u);
      EXPECT_EQ(m.non_manifold_edges, 0u);
    } else {
      EXPECT_TRUE(m.closed_manifold()) << m.name;
    }
  }
  EXPECT_TRUE(saw_ground);
  EXPECT_TRUE(saw_open_box);
}

// What lab 9's check counts (transform feedback): one box lit from above at an angle shows the light its
// top and two sides (six triangles), outlined by six silhouette edges (a hexagon).
// The box stands alone (scene.ground=0): the ground a scene without one gets would add its own volume.
TEST_F(LightsTest, VolumeTrianglesSortSidesFromCaps) {
  Scene s;
  Mesh box = make_box({0.0f, 1.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, {0.5f, 0.5f, 0.5f});
  box.name = "box";
  s.meshes.push_back(box);
  Renderer r;
  r.set_scene(s);
  Features hooks;
  hooks.technique = ShadowTechnique::ShadowVolumes;
  ASSERT_TRUE(r.set_features(hooks)) << r.shader_error();
  r.render(lab_set({"scene.ground=0", "light.type=directional", "light.azimuth=35", "light.elevation=50"}), request(OrbitCamera::framing(s.bounds())));
  const VolumeTriangles open = r.count_volume_triangles(false);
  EXPECT_EQ(open.sides, 12);  // six silhouette edges, a quad (two triangles) each
  EXPECT_EQ(open.near_caps, 0);
  EXPECT_EQ(open.far_caps, 0);
  const VolumeTriangles closed = r.count_volume_triangles(true);
  EXPECT_EQ(closed.sides, 12);
  EXPECT_EQ(closed.near_caps, 6);  // the lit triangles
  EXPECT_EQ(closed.far_caps, 0) << "a directional light's far cap has no area and is left out";
  r.render(lab_set({"scene.ground=0", "light.type=point", "light.position_x=3", "light.position_y=4", "light.position_z=2"}),
           request(OrbitCamera::framing(s.bounds())));
  const VolumeTriangles point = r.count_volume_triangles(true);
  EXPECT_EQ(point.sides, 12);
  EXPECT_EQ(point.near_caps, 6);
  EXPECT_EQ(point.far_caps, 6);
  // Lab 9's stock exercise emits nothing: the capture must still link (its output is written in main).
  ASSERT_TRUE(r.set_features(find_lab(9)->hooks(Impl::Exercise))) << r.shader_error();
  r.render(lab_set({"scene.ground=0", "light.type=point"}), request(OrbitCamera::framing(s.bounds())));
  const VolumeTriangles none = r.count_volume_triangles(true);
  EXPECT_EQ(none.sides + none.near_caps + none.far_caps, 0);
}

TEST_F(LightsTest, CubeMapSixPassesAndOnePassStoreTheSameDistances) {
  Renderer r;
  r.set_scene(scene);
  Features hooks;
  hooks.light = LightType::Point;
  ASSERT_TRUE(r.set_features(hooks)) << r.shader_error();
  const OrbitCamera camera = OrbitCamera::framing(scene.bounds(), 30.0f, 60.0f);
  r.render(lab_set({"point.single_pass=false"}), request(camera));
  EXPECT_EQ(r.stats().cube_faces, 6);
  int size = 0;
  std::vector<float> six[6];
  for (int f = 0; f < 6; ++f) six[f] = r.read_cube_face(f, &size);
  r.render(lab_set({"point.single_pass=true"}), request(camera));
  EXPECT_EQ(r.stats().cube_faces, 12);
  for (int f = 0; f < 6; ++f) {
    const std::vector<float> one = r.read_cube_face(f, &size);
    ASSERT_EQ(one.size(), six[f].size());
    for (std::size_t i = 0; i < one.size(); ++i) ASSERT_NEAR(one[i], six[f][i], 1e-5f) << "face " << f << " texel " << i;
  }
  // The -Y face looks at the ground 3 units below the light: its centre texel stores about 3.
  const std::vector<float> down = r.read_cube_face(3, &size);
  EXPECT_NEAR(down[static_cast<std::size_t>(size / 2) * size + size / 2], 3.0f, 0.05f);
  // And the shadows agree with the oracle casting toward the light's position.
  const Oracle oracle(scene);
  r.render(lab_set({"point.single_pass=true", "shadow.slope_bias=2"}), request(camera));  // lab 8's bias
  EXPECT_GE(agreement(r, oracle, false), 0.995);
}

TEST_F(LightsTest, TargetsExistOnlyWhileALabUsesThem) {
  Renderer r;
  r.set_scene(scene);
  const OrbitCamera camera = OrbitCamera::framing(scene.bounds());
  const int textures_before = live_gl_objects(GlKind::Texture);
  r.render(lab_set({}), request(camera));
  const int textures_depth_lab = live_gl_objects(GlKind::Texture) - textures_before;
  EXPECT_EQ(live_gl_objects(GlKind::Sampler), 0) << "no comparison sampler without hardware PCF";
  // Hardware PCF: one sampler object, no extra texture.
  Features pcf;
  pcf.shadow_test = "pcf";
  ASSERT_TRUE(r.set_features(pcf)) << r.shader_error();
  r.render(lab_set({"pcf.hardware=true", "pcf.kernel=3"}), request(camera));
  EXPECT_EQ(live_gl_objects(GlKind::Sampler), 1);
  // A point light: two cube maps (distance, depth) replace the 2D depth map.
  Features point;
  point.light = LightType::Point;
  ASSERT_TRUE(r.set_features(point)) << r.shader_error();
  r.render(lab_set({}), request(camera));
  EXPECT_EQ(live_gl_objects(GlKind::Texture) - textures_before, textures_depth_lab + 1);
  // Back to a directional light: the cube maps are freed.
  ASSERT_TRUE(r.set_features({})) << r.shader_error();
  r.render(lab_set({}), request(camera));
  EXPECT_EQ(live_gl_objects(GlKind::Texture) - textures_before, textures_depth_lab);
  EXPECT_THROW(r.read_cube_face(0, nullptr), std::logic_error);
}

// The lit program compiled for PCF's settings (kernel and comparison as constants) draws exactly the
// image and visibility the generic program (reading them as uniforms) draws: for the renderer's PCF, the
// stock exercise, and two right answers of the exam corpus written differently, every kernel, both
// comparisons. Switching back to settings drawn before reuses their program.
TEST_F(LightsTest, LitProgramCompiledForThePcfSettingsDrawsTheGenericImage) {
  Renderer r;
  r.set_scene(scene);
  const OrbitCamera camera = OrbitCamera::framing(scene.bounds());
  const std::string answers = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/answers/06_pcf/right/";
  for (const std::string& file : {std::string("shaders/shadow/pcf.glsl"), std::string("labs/06_pcf/exercise.glsl"),
                                 answers + "two_loops_step__exercise.glsl", answers + "per_tap_reach_bias__exercise.glsl"}) {
    Features pcf;
    pcf.shadow_test = "pcf";  // PCF's uniforms, read by each of these files
    pcf.includes["lab/visibility.glsl"] = file;
    ASSERT_TRUE(r.set_features(pcf)) << r.shader_error();
    for (const char* kernel : {"1", "3", "5", "9"})
      for (const char* hardware : {"false", "true"}) {
        const ParamSet p = lab_set({"shadow.map_size=512", "light.elevation=40",
                                    (std::string("pcf.kernel=") + kernel).c_str(),
                                    (std::string("pcf.hardware=") + hardware).c_str()});
        const std::string what = file + " kernel " + kernel + " hardware " + hardware;
        r.set_lit_constants(false);
        r.render(p, request(camera));
        EXPECT_TRUE(r.drawn_lit_constants().empty()) << what;
        const auto generic_color = r.read_color();
        const auto generic_visibility = r.read_visibility();
        r.set_lit_constants(true);
        r.render(p, request(camera));
        const LitConstants expected = {{"u_pcf_radius", std::to_string((kernel[0] - '0') / 2)},
                                       {"u_pcf_hardware", hardware[0] == 't' ? "1" : "0"}};
        EXPECT_EQ(r.drawn_lit_constants(), expected) << what;
        EXPECT_TRUE(r.read_color() == generic_color) << what;
        const auto visibility = r.read_visibility();
        ASSERT_EQ(visibility.size(), generic_visibility.size());
        long differ = 0, partial = 0;
        for (std::size_t i = 0; i < visibility.size(); ++i) {
          differ += visibility[i] != generic_visibility[i];
          partial += visibility[i] > 0.0f && visibility[i] < 1.0f;
        }
        EXPECT_EQ(differ, 0) << what;
        if (file != "labs/06_pcf/exercise.glsl" && (kernel[0] != '1' || hardware[0] == 't')) {
          EXPECT_GT(partial, 0) << what << ": a filtered edge, so the kernel is seen to act";
        }
      }
  }
  EXPECT_TRUE(r.shader_error().empty()) << r.shader_error();
}

TEST_F(LightsTest, GeometryShaderDebugViewsDrawOnlyWhenOn) {
  Renderer r;
  r.set_scene(scene);
  const OrbitCamera camera = OrbitCamera::framing(scene.bounds());
  FrameRequest req = request(camera);
  req.gbuffer = false;
  r.render(lab_set({}), req);
  const auto plain = r.read_color();
  auto has_pass = [&](const char* name) {
    for (const auto& p : r.stats().passes)
      if (p.name == name) return true;
    return false;
  };
  const std::pair<const char*, const char*> views[] = {
      {"view.flat_normals=true", "flat_normals_view"}, {"view.normals=true", "normals_view"}, {"view.volumes=true", "volumes_view"}};
  for (const auto& [view, pass] : views) EXPECT_FALSE(has_pass(pass)) << pass;
  for (const auto& [view, pass] : views) {
    r.render(lab_set({view}), req);
    const auto with_view = r.read_color();
    std::size_t changed = 0;
    for (std::size_t i = 0; i < plain.size(); i += 4)
      changed += plain[i] != with_view[i] || plain[i + 1] != with_view[i + 1] || plain[i + 2] != with_view[i + 2];
    EXPECT_GT(changed, 500u) << view;
    EXPECT_TRUE(has_pass(pass)) << view;
  }
}

TEST_F(LightsTest, EveryNewLabBuildsItsExerciseAndSolution) {
  Renderer r;
  r.set_scene(scene);
  for (int number : {0, 6, 7, 8, 9}) {
    const Lab* lab = find_lab(number);
    ASSERT_NE(lab, nullptr) << number;
    for (Impl impl : {Impl::Exercise, Impl::Solution}) {
      EXPECT_TRUE(r.set_features(lab->hooks(impl))) << "lab " << number << " " << impl_name(impl) << ": " << r.shader_error();
      r.render(lab_params(*lab), request(OrbitCamera::framing(scene.bounds()), 64, 36));
      EXPECT_TRUE(r.shader_error().empty()) << r.shader_error();
    }
  }
}

}  // namespace
}  // namespace shadowlab
