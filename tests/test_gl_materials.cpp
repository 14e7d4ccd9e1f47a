// Materials as far as shadows need them (issue 22): a textured model is drawn with its texture, an
// alpha-masked caster cuts the same holes into the view, the shadow map and the oracle's truth, a bad
// image is a checker with a warning naming it, and a model with no ground of its own gets one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/billboards.h"
#include "core/gltf_loader.h"
#include "oracle/metrics.h"
#include "oracle/oracle.h"
#include "renderer/renderer.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = fs::path(SHADOWLAB_SOURCE_DIR) / "assets" / "models";
const fs::path kAlphaMask = fs::path(SHADOWLAB_SOURCE_DIR) / "tests" / "data" / "alpha_mask";

// Where a world point lands in the last frame (y from the bottom), or false when off screen.
bool project(const Renderer& r, const glm::vec3& p, int* x, int* y) {
  const glm::vec4 c = r.camera_projection() * r.camera_view() * glm::vec4(p, 1.0f);
  if (c.w <= 0.0f) return false;
  *x = static_cast<int>((c.x / c.w * 0.5f + 0.5f) * static_cast<float>(r.width()));
  *y = static_cast<int>((c.y / c.w * 0.5f + 0.5f) * static_cast<float>(r.height()));
  return *x >= 0 && *y >= 0 && *x < r.width() && *y < r.height();
}

glm::vec3 color_at(const Renderer& r, const std::vector<std::uint8_t>& rgba, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(r.height() - 1 - y) * static_cast<std::size_t>(r.width()) + x) * 4;
  return glm::vec3(rgba[i], rgba[i + 1], rgba[i + 2]) / 255.0f;
}

FrameRequest request(const Scene& scene, const ParamSet& params) {
  FrameRequest req;
  req.camera = frame_scene_camera(scene, params);
  req.width = 640;
  req.height = 480;
  req.gbuffer = true;
  return req;
}

// The rendered visibility against the oracle's, as a check grades it (interior pixels, 2-texel band).
Metrics against_oracle(Renderer& r) {
  const Oracle oracle(r.scene());
  const Truth truth = oracle.evaluate(r.read_gbuffer(), oracle_light(r), BandSpec{});
  return compare(truth, r.read_visibility());
}

// The mesh of this name (the loader's order of meshes is not the file's).
Mesh& named(Scene& s, const std::string& name) {
  for (Mesh& m : s.meshes)
    if (m.name == name) return m;
  throw std::runtime_error("no mesh named " + name);
}

class MaterialsTest : public GlTest {
 protected:
  ParamSet params{renderer_param_specs()};
};

TEST(MaterialsLoad, TexturedModelsCarryTheirTextureCoordinatesAndDecodedImage) {
  std::vector<std::string> warnings;
  const Scene box = load_gltf(kModels / "BoxTextured" / "BoxTextured.gltf", {}, &warnings);
  ASSERT_EQ(box.textures.size(), 1u);
  const Texture& t = box.textures[0];
  EXPECT_TRUE(t.problem.empty()) << t.problem;
  ASSERT_TRUE(t.rgba);
  EXPECT_GT(t.width, 8);
  EXPECT_EQ(t.rgba->size(), static_cast<std::size_t>(t.width) * t.height * 4);
  ASSERT_EQ(box.meshes.size(), 1u);
  EXPECT_EQ(box.meshes[0].texture, 0);
  EXPECT_EQ(box.meshes[0].uvs.size(), box.meshes[0].positions.size());
  EXPECT_TRUE(warnings.empty());
}

TEST(MaterialsLoad, AlphaMaskSceneHasItsMaskCutoffAndVertexColours) {
  Scene s = load_gltf(kAlphaMask / "alpha_mask.gltf");
  ASSERT_EQ(s.meshes.size(), 2u);
  const Mesh& quad = named(s, "cut-out quad");
  EXPECT_EQ(quad.alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(quad.alpha_cutoff, 0.5f);
  EXPECT_EQ(quad.color, glm::vec3(0.9f, 0.5f, 0.2f));
  // The 4 x 4 checker: texel (0, 0) opaque, (1, 0) cut out; the triangle's barycentrics pick them.
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_FLOAT_EQ(sample_texture(s.textures[0], {0.125f, 0.125f}).a, 1.0f);
  EXPECT_FLOAT_EQ(sample_texture(s.textures[0], {0.375f, 0.125f}).a, 0.0f);
  const Mesh& ground = named(s, "ground");
  ASSERT_EQ(ground.colors.size(), 4u);
  EXPECT_NEAR(ground.colors[0].b, 0.9f, 1e-6f);
  EXPECT_TRUE(has_ground(s));
}

// A corrupt image and a missing one: the model loads, each image is a checker, and a warning names it.
TEST(MaterialsLoad, BadOrMissingImageIsACheckerWithAWarningNamingIt) {
  const fs::path dir = fs::temp_directory_path() / "shadowlab_bad_image";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const char* f : {"alpha_mask.gltf", "alpha_mask.bin"}) fs::copy_file(kAlphaMask / f, dir / f);
  {
    std::ofstream(dir / "mask.png") << "this is not a PNG";
    std::vector<std::string> warnings;
    const Scene s = load_gltf(dir / "alpha_mask.gltf", {}, &warnings);
    ASSERT_EQ(s.textures.size(), 1u);
    EXPECT_FALSE(s.textures[0].problem.empty());
    EXPECT_EQ(s.textures[0].width, 64);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("mask.png"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("checker"), std::string::npos) << warnings[0];
  }
  fs::remove(dir / "mask.png");
  std::vector<std::string> warnings;
  const Scene s = load_gltf(dir / "alpha_mask.gltf", {}, &warnings);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_NE(s.textures[0].problem.find("cannot be read"), std::string::npos) << s.textures[0].problem;
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.back().find("mask.png"), std::string::npos) << warnings.back();
  fs::remove_all(dir);
}

TEST(MaterialsLoad, GroundIsAddedOnlyWhereTheSceneHasNone) {
  const Scene duck = load_gltf(kModels / "Duck" / "Duck.gltf");
  EXPECT_FALSE(has_ground(duck));
  const Scene grounded = with_ground(duck, true);
  ASSERT_EQ(grounded.meshes.size(), duck.meshes.size() + 1);
  EXPECT_TRUE(grounded.meshes.back().ground);
  EXPECT_FLOAT_EQ(grounded.bounds().min.y, duck.bounds().min.y);
  EXPECT_TRUE(has_ground(grounded));
  EXPECT_TRUE(has_ground(make_default_scene()));
  EXPECT_TRUE(has_ground(make_stacked_occluders_scene()));
}

// The cut-out quad over the blue ground, seen from the framing camera: each of the checker's 16 cells
// shows the quad's orange where the texel is opaque and the ground's blue through the holes; its
// shadow has the same holes, in the shadow map as in the oracle's truth.
TEST_F(MaterialsTest, AlphaMaskedCasterCutsHolesInTheViewTheShadowMapAndTheOracle) {
  const Scene scene = load_gltf(kAlphaMask / "alpha_mask.gltf");
  params.set("light.elevation", 60.0);
  Renderer r;
  r.set_scene(scene);
  r.render(params, request(scene, params));
  const std::vector<std::uint8_t> rgba = r.read_color();
  int opaque = 0, holes = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      // Texel (i, j) covers u in [i/4, (i+1)/4], v likewise; u runs along x from -1, v along z from -1.
      const glm::vec3 centre(-1.0f + 0.5f * (static_cast<float>(i) + 0.5f), 1.0f, -1.0f + 0.5f * (static_cast<float>(j) + 0.5f));
      int x = 0, y = 0;
      ASSERT_TRUE(project(r, centre, &x, &y));
      const glm::vec3 c = color_at(r, rgba, x, y);
      if ((i + j) % 2 == 0) {
        EXPECT_GT(c.r, c.b + 0.2f) << "cell " << i << "," << j << " should be the quad's orange";
        ++opaque;
      } else {
        EXPECT_GT(c.b, c.r + 0.05f) << "cell " << i << "," << j << " should show the blue ground through the hole";
        ++holes;
      }
    }
  EXPECT_EQ(opaque, 8);
  EXPECT_EQ(holes, 8);

  const Metrics m = against_oracle(r);
  EXPECT_GT(m.interior_lit, 500u);
  EXPECT_GT(m.interior_shadowed, 500u);
  EXPECT_LT(m.acne_rate, 0.005) << "the shadow map darkens pixels the oracle lights (holes not cut)";
  EXPECT_LT(m.leak_rate, 0.005) << "the shadow map lights pixels the oracle shadows";

  // The same quad made opaque: the oracle (built from the same scene) now shadows where the holes were,
  // so the two disagree unless both follow the material; this is what the test above would miss.
  Scene opaque_scene = scene;
  named(opaque_scene, "cut-out quad").alpha_mode = AlphaMode::Opaque;
  Renderer o;
  o.set_scene(opaque_scene);
  o.render(params, request(opaque_scene, params));
  const Metrics mo = against_oracle(o);
  EXPECT_GT(mo.interior_shadowed, m.interior_shadowed + 500u) << "the holes let light through only when masked";
  EXPECT_LT(mo.leak_rate, 0.005);
}

// Duck: a textured model with no ground. Its texture shows (the duck is yellow: red and green well
// above blue, where the untextured grey had them equal), a ground is added under it, and the shadow
// the ground receives agrees with the oracle.
TEST_F(MaterialsTest, TexturedModelIsDrawnWithItsTextureAndShadowsTheAddedGround) {
  const Scene duck = load_gltf(kModels / "Duck" / "Duck.gltf");
  Renderer r;
  r.set_scene(duck);
  r.render(params, request(duck, params));
  ASSERT_TRUE(r.ground_added());
  ASSERT_EQ(r.scene().meshes.size(), duck.meshes.size() + 1);
  const GBuffer g = r.read_gbuffer();
  const std::vector<std::uint8_t> rgba = r.read_color();
  const Bounds box = duck.bounds();
  glm::dvec3 sum(0.0);
  long n = 0;
  for (int y = 0; y < r.height(); ++y)
    for (int x = 0; x < r.width(); ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * r.width() + x;
      if (!g.covered[i] || g.position[i].y < box.min.y + 0.1f * box.extent().y) continue;  // the duck, not the ground
      sum += glm::dvec3(color_at(r, rgba, x, y));
      ++n;
    }
  ASSERT_GT(n, 2000);
  const glm::dvec3 mean = sum / static_cast<double>(n);
  EXPECT_GT(mean.r, 1.5 * mean.b) << mean.r << " " << mean.g << " " << mean.b;
  EXPECT_GT(mean.g, 1.2 * mean.b) << mean.r << " " << mean.g << " " << mean.b;

  const Metrics m = against_oracle(r);
  EXPECT_GT(m.interior_shadowed, 500u) << "the duck's shadow falls on the added ground";
  EXPECT_LT(m.acne_rate, 0.01);
  EXPECT_LT(m.leak_rate, 0.01);

  // Off: no ground, nothing under the duck receives its shadow.
  params.set("scene.ground", 0.0);
  r.render(params, request(duck, params));
  EXPECT_FALSE(r.ground_added());
  EXPECT_EQ(r.scene().meshes.size(), duck.meshes.size());
}

// Every shadow technique on the cut-out quad, each lab's solution as `shadowlab bench` runs it: the
// map's holes (or, for shadow volumes, their absence) against the oracle. `wrong_pixels` counts the graded
// interior pixels (the check's band: 2 texels, plus a screen band of 4 pixels for the soft techniques'
// blurred edges) whose rendered lit/shadowed answer differs from the truth.
struct MaskCase {
  const char* name;
  int lab;
  std::vector<std::pair<const char*, const char*>> sets;
};

std::ostream& operator<<(std::ostream& os, const MaskCase& c) { return os << c.name; }

// A masked quad's shadow gets fewer graded pixels wrong than this against the masked truth; the same frame
// with the quad drawn opaque (no holes anywhere, as a pass ignoring the mask would draw its shadow) more.
// Measured (640 x 480, the check's band and a 4-pixel screen band): with the holes 0 on every technique; with
// the quad drawn opaque 489 (spot) to 2,273 (point light); with the mask ignored in the shadow pass alone
// (the view cut, the map not; measured once with the masked casters drawn by the pass's own program)
// 661 to 2,600.
constexpr double kMaxWrongPixels = 100.0;

// Graded interior pixels whose lit/shadowed answer differs from the truth.
double wrong_pixels(const Metrics& m) {
  return m.acne_rate * static_cast<double>(m.interior_lit) + m.leak_rate * static_cast<double>(m.interior_shadowed);
}

// Renders `scene` with the case's lab solution (light at elevation 60) and grades it against the truth of
// `truth_of` (the same scene, or another version of it).
Metrics render_case(const MaskCase& c, const Scene& scene, const Scene& truth_of, Renderer& r) {
  const Lab* lab = find_lab(c.lab);
  if (!lab) throw std::runtime_error("no lab " + std::to_string(c.lab));
  ParamSet p = lab_params(*lab);
  p.set("light.elevation", 60.0);
  p.set("view.debug_quad", 0.0);
  for (const auto& [k, v] : c.sets) p.set_from_string(k, v);
  EXPECT_TRUE(r.set_features(lab->hooks(Impl::Solution))) << r.shader_error();
  r.set_scene(scene);
  r.render(p, request(scene, p));
  EXPECT_EQ(r.shader_error(), "");
  BandSpec screen = grading_band();
  screen.fixed_screen_pixels = 4;
  const Oracle oracle(truth_of);
  Truth truth = oracle.evaluate(r.read_gbuffer(), oracle_light(r), screen);
  if (c.lab != 9) {  // shadow volumes have no texels: the screen band alone
    const Truth texels = oracle.evaluate(r.read_gbuffer(), oracle_light(r), grading_band());
    for (std::size_t i = 0; i < truth.interior.size(); ++i) truth.interior[i] &= texels.interior[i];
  }
  return compare(truth, r.read_visibility());
}

class AlphaMaskTechniqueTest : public MaterialsTest, public ::testing::WithParamInterface<MaskCase> {};

TEST_P(AlphaMaskTechniqueTest, MaskedCasterCutsHolesInTheTechniquesShadow) {
  const Scene scene = load_gltf(kAlphaMask / "alpha_mask.gltf");
  Scene opaque = scene;
  named(opaque, "cut-out quad").alpha_mode = AlphaMode::Opaque;
  Renderer r, o;
  const Metrics masked = render_case(GetParam(), scene, scene, r);
  const Metrics no_holes = render_case(GetParam(), opaque, scene, o);
  std::printf("    %-22s wrong pixels with the holes %.0f, without them %.0f (of %llu interior)\n", GetParam().name,
              wrong_pixels(masked), wrong_pixels(no_holes),
              static_cast<unsigned long long>(masked.interior_lit + masked.interior_shadowed));
  EXPECT_GT(masked.interior_lit, 500u);
  EXPECT_GT(masked.interior_shadowed, 200u);  // 252 measured: the holes' shadows are small at 640 x 480
  EXPECT_LT(wrong_pixels(masked), kMaxWrongPixels) << "the shadow lacks the holes the view and the oracle have";
  EXPECT_GT(wrong_pixels(no_holes), kMaxWrongPixels) << "the scene does not tell a shadow with holes from one without";
}

INSTANTIATE_TEST_SUITE_P(
    Techniques, AlphaMaskTechniqueTest,
    ::testing::Values(MaskCase{"hard", 1, {}}, MaskCase{"pcf 5x5", 6, {{"pcf.kernel", "5"}}}, MaskCase{"spot", 7, {}},
                      MaskCase{"point six passes", 8, {{"point.single_pass", "false"}}},
                      MaskCase{"point one pass", 8, {{"point.single_pass", "true"}}}, MaskCase{"vsm", 3, {}},
                      MaskCase{"vsm blurred", 5, {}}, MaskCase{"evsm", 13, {}}, MaskCase{"msm", 14, {}},
                      MaskCase{"csm", 12, {}}),
    [](const ::testing::TestParamInfo<MaskCase>& info) {
      std::string name = info.param.name;
      std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
      return name;
    });

// Shadow volumes cannot follow a texture: a silhouette is found from the mesh's edges, and a cut-out's
// edges are in its texture. Masked casters' volumes are the whole triangles (solid): their shadow is the
// opaque quad's. Measured against the truth: solid volumes err on the holes' shadow, volumes leaving the
// masked caster out (the other choice) on the opaque cells' shadow.
TEST_F(MaterialsTest, ShadowVolumesCastMaskedCastersSolid) {
  const Scene scene = load_gltf(kAlphaMask / "alpha_mask.gltf");
  Scene opaque = scene, left_out = scene;
  named(opaque, "cut-out quad").alpha_mode = AlphaMode::Opaque;
  named(left_out, "cut-out quad").casts_shadow = false;
  const MaskCase volumes{"volumes", 9, {{"volume.method", "z-fail"}}};
  Renderer r, x;
  const Metrics solid_vs_opaque = render_case(volumes, scene, opaque, r);
  const Metrics solid = render_case(volumes, scene, scene, r);
  const Metrics excluded = render_case(volumes, left_out, scene, x);
  // Measured: solid 664 (0 against the opaque quad's truth), left out 252.
  std::printf("    volumes: wrong pixels solid %.0f (against the opaque quad's truth %.0f), left out %.0f\n", wrong_pixels(solid),
              wrong_pixels(solid_vs_opaque), wrong_pixels(excluded));
  EXPECT_LT(wrong_pixels(solid_vs_opaque), kMaxWrongPixels) << "masked casters' volumes are drawn solid";
  EXPECT_GT(wrong_pixels(solid), kMaxWrongPixels);
}

}  // namespace

// Lab 11's oracle: the light-facing billboard quads as MASK triangles whose alpha is the analytic cut-out
// (Mesh::shape_alpha). A shadow ray through a point of the quad is blocked exactly where
// billboard_alpha(uv) reaches the cutoff, at any cutoff; the quad stands upright and faces the light.
TEST(Billboards, OracleCutsTheSameShapeAsTheShaders) {
  const glm::vec3 to_light = direction_from_angles(35.0f, 50.0f), base(1.0f, 0.0f, -2.0f);
  for (float cutoff : {0.3f, 0.5f, 0.7f}) {
    BillboardSize size;
    size.cutoff = cutoff;
    Scene scene;
    scene.meshes.push_back(billboard_light_quads({base}, size, to_light));
    const Mesh& quad = scene.meshes[0];
    ASSERT_EQ(quad.triangle_count(), 2u);
    EXPECT_NEAR(glm::dot(quad.normals[0], to_light), glm::length(glm::vec3(to_light.x, 0, to_light.z)), 1e-5f);
    EXPECT_FLOAT_EQ(quad.positions[2].y - quad.positions[0].y, size.height);
    const Oracle oracle(scene);
    const glm::vec3 right = quad.positions[1] - quad.positions[0], up = quad.positions[2] - quad.positions[0];
    int blocked = 0, open = 0, wrong = 0;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        const glm::vec2 uv((x + 0.5f) / 40.0f, (y + 0.5f) / 40.0f);
        const float alpha = billboard_alpha(uv);
        if (std::abs(alpha - cutoff) < 1e-3f) continue;  // rounding of the hit's uv decides
        const glm::vec3 p = quad.positions[0] + uv.x * right + uv.y * up;
        const bool hit = oracle.occluded(p - 2.0f * to_light, to_light, 4.0f);
        (hit ? blocked : open) += 1;
        wrong += hit != (alpha >= cutoff);
      }
    EXPECT_EQ(wrong, 0) << "cutoff " << cutoff;
    EXPECT_GT(blocked, 100) << "cutoff " << cutoff;  // the crown and trunk
    EXPECT_GT(open, 100) << "cutoff " << cutoff;     // the gaps and the corners
  }
}

}  // namespace shadowlab
