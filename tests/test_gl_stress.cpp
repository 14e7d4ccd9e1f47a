// The numerical stress suite on the GPU path (headless GL): each case renders with a lab's solution,
// checks the raw visibility (no NaN or Inf, every value in [0, 1]) and the moments (finite), measures
// the error against the oracle, and asserts the outcome the case names. The limits come from the figures
// measured here (printed as a table; README "Limits, measured"). The CPU side of the light fit is in
// test_stress.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "app/stats_text.h"
#include "grading/check.h"
#include "grading/lab.h"
#include "app/placement_sweep.h"
#include "labs/registry.h"
#include "renderer/moments_pass.h"
#include "core/vsm_params.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

struct Outcome {
  Metrics metrics;
  long non_finite = 0;   // NaN or Inf in the visibility (and in the moments, for VSM labs)
  long out_of_range = 0; // visibility outside [0, 1]
  double error = 0.0;    // acne + leak over all valid pixels
  double negative_variance = 0.0;  // share of covered moments texels with E[z^2] - E[z]^2 < 0
  std::string warning;             // the panel's precision warning after the frame
};

Scene transformed(const Scene& s, const glm::mat4& m) {
  Scene out = s;
  for (auto& mesh : out.meshes) transform_mesh(mesh, m);
  return out;
}

class StressGlTest : public GlTest {
 protected:
  // Renders `scene` with lab `lab`'s solution and the assignments, at 480 x 270, and measures it.
  // The camera frames `view` (default: the whole scene).
  Outcome run(const char* name, const char* expected, int lab, const Scene& scene,
              std::initializer_list<std::string> assignments, const Bounds* view = nullptr) {
    const Lab& l = *find_lab(lab);
    Renderer renderer;
    CheckContext ctx(renderer, l, Impl::Solution, scene, {});
    ParamSet p = ctx.params();
    p.set("view.debug_quad", 0.0);
    // The stretched scenes' marker far below the floor would otherwise get a ground of its own (the
    // scene's lowest quarter holds no floor): the ranges are about depth precision, not that plane.
    p.set("scene.ground", 0.0);
    for (const auto& a : assignments) {
      const std::string key = a.substr(0, a.find('='));
      if (!p.find(key) && key.rfind("vsm.", 0) == 0) p.declare(vsm_param_specs({key}).at(0));  // not on the lab's panel
      p.apply_assignment(a);
    }
    const auto m = ctx.measure(p, l.hooks(Impl::Solution), name, view, {}, 480, 270);
    Outcome o;
    o.metrics = m.metrics;
    for (float v : m.visibility) {
      if (!std::isfinite(v)) ++o.non_finite;
      else if (v < 0.0f || v > 1.0f) ++o.out_of_range;
    }
    if (l.hooks(Impl::Solution).technique == ShadowTechnique::Moments) {
      int size = 0;
      const std::vector<float> moments = renderer.read_moments(&size);
      for (float v : moments)
        if (!std::isfinite(v)) ++o.non_finite;
      o.negative_variance = MomentsPass::negative_variance_share(moments);
      // The renderer measured the same for the panel (RG16F only).
      const double reported = renderer.stats().moments_negative_variance;
      if (reported >= 0.0) {
        EXPECT_EQ(reported, o.negative_variance) << name;
      }
      o.warning = precision_warning(renderer.stats());
      std::printf("  %-28s negative variance in %.4f of covered texels\n", name, o.negative_variance);
    }
    o.error = m.metrics.acne_rate_all + m.metrics.leak_rate_all;
    std::printf("  %-28s acne %.5f  leak %.5f  bleed %.5f  mae %.5f/%.5f  error %.5f  nan %ld  out %ld  (%s)\n", name,
                m.metrics.acne_rate_all, m.metrics.leak_rate_all, m.metrics.bleeding_rate, m.metrics.mae_interior,
                m.metrics.mae_edge, o.error, o.non_finite, o.out_of_range, expected);
    EXPECT_EQ(o.non_finite, 0) << name;
    EXPECT_EQ(o.out_of_range, 0) << name;
    EXPECT_GT(m.metrics.valid_pixels, 1000u) << name << ": the camera sees the scene";
    return o;
  }
};

// The default scene plus a small marker far below it: the fitted box's depth range grows with `depth`
// while what the camera sees stays the same, so the stored depth's precision is spread ever thinner.
Scene stretched_scene(float depth) {
  Scene s = make_default_scene();
  if (depth > 12.0f) {
    Mesh marker = make_box({0, -depth, 0}, {0.1f, 0.1f, 0.1f}, glm::vec3(0.5f));
    marker.casts_shadow = false;  // it only stretches the box; it shadows nothing
    s.meshes.push_back(marker);
  }
  return s;
}

std::string range_label(float depth) {
  char label[64];
  std::snprintf(label, sizeof label, "range %.0f", static_cast<double>(depth));
  return label;
}

// The bias and the minimum variance are in units of the fitted box's depth: scale them by 12 / range to
// keep the same world-space amounts (otherwise a range of 12000 turns lab 1's 0.005 into 60 units of
// bias and every shadow detaches: measured leak 100 % with every format).
std::string world_constant(const char* key, double value, float depth, int power = 1) {
  return std::string(key) + "=" + std::to_string(value * std::pow(12.0 / depth, power));
}

TEST_F(StressGlTest, DepthFormatsOverGrowingDepthRanges) {
  // 16-bit fixed point steps 1/65536 of the range, 24-bit 1/16.7M, 32F ~2^-24 near 1.
  const Bounds view = make_default_scene().bounds();
  for (float depth : {12.0f, 1200.0f, 12000.0f}) {
    const Scene s = stretched_scene(depth);
    const std::string l = range_label(depth);
    const std::string bias = world_constant("shadow.bias", 0.005, depth);
    const Outcome as_is = run((l + " depth 24, bias as is").c_str(), "shadows detach at large ranges", 1, s,
                              {"light.elevation=90", "shadow.depth_format=24"}, &view);
    const Outcome d16 = run((l + " depth 16").c_str(), "acne once the step outgrows the bias", 1, s,
                            {"light.elevation=90", "shadow.depth_format=16", bias}, &view);
    const Outcome d24 = run((l + " depth 24").c_str(), "lab 1's bounds", 1, s, {"light.elevation=90", "shadow.depth_format=24", bias}, &view);
    const Outcome d32 = run((l + " depth 32F").c_str(), "as 24", 1, s, {"light.elevation=90", "shadow.depth_format=32F", bias}, &view);
    EXPECT_GE(d16.error, d24.error - 1e-4) << "16-bit cannot beat 24-bit";
    EXPECT_GE(d16.metrics.acne_rate, d24.metrics.acne_rate) << depth;
    if (depth <= 1200.0f) {
      // Measured: 0.0022 for every format at 12 and 1200; lab 1's bounds hold.
      EXPECT_LE(d24.metrics.acne_rate, 0.001) << depth;
      EXPECT_LE(d32.metrics.acne_rate, 0.001) << depth;
      EXPECT_NEAR(d16.error, d24.error, 1e-3) << depth;
      EXPECT_NEAR(as_is.error, d24.error, 1e-3) << depth;
    } else {
      // 12000: lab 1's constant bias (0.0005 of the range) is 6 world units: every shadow detaches
      // (measured leak 1.0). With the bias held at 0.06 world units, float32 arithmetic in the passes
      // (not the stored format) limits: acne 2.5 % with 24-bit and 32F, 2.7 % with 16-bit.
      EXPECT_GE(as_is.metrics.leak_rate, 0.99);
      EXPECT_GT(d24.metrics.acne_rate, 0.005) << "if this improves, update the README's limits";
      EXPECT_LT(d24.metrics.acne_rate, 0.05);
      EXPECT_NEAR(d32.error, d24.error, 2e-3);
    }
  }
}

TEST_F(StressGlTest, MomentsFormatsOverGrowingDepthRanges) {
  // RG16F stores z in [0, 1] to 2^-11 near 1: the world-space step grows with the range, and
  // E[z^2] - E[z]^2 cancels to nothing.
  const Bounds view = make_default_scene().bounds();
  for (float depth : {12.0f, 120.0f, 1200.0f, 12000.0f}) {
    const Scene s = stretched_scene(depth);
    const std::string l = range_label(depth);
    const std::string bias = world_constant("shadow.bias", 0.005, depth);
    const Outcome f32 = run((l + " RG32F").c_str(), "within lab 4's bounds", 4, s,
                            {"vsm.format=RG32F", "light.elevation=90", bias}, &view);
    const Outcome f16 = run((l + " RG16F").c_str(), "worse as the range grows", 4, s,
                            {"vsm.format=RG16F", "light.elevation=90", bias}, &view);
    EXPECT_EQ(f32.negative_variance, 0.0) << depth;
    EXPECT_GT(f16.negative_variance, 0.01) << depth;  // measured 0.021, 0.052, 0.9998, 1.0
    if (depth <= 120.0f) {
      EXPECT_LE(f32.metrics.acne_rate, 0.005) << depth;
      EXPECT_LE(f32.metrics.bleeding_rate, 0.01) << depth;
    } else {
      // The minimum variance is in depth^2 units of the box: 2e-6 is a standard deviation of 1.7 world
      // units at a 1200-unit range, so light passes every shadow whatever the format (leak 0.67, 1.0).
      EXPECT_GT(f32.metrics.leak_rate, 0.5) << depth;
      EXPECT_GT(f16.negative_variance, 0.9) << depth;
    }
    // What the panel says: nothing for RG32F; a warning for RG16F, naming the fix.
    EXPECT_EQ(f32.warning, "") << depth;
    EXPECT_NE(f16.warning.find("RG32F"), std::string::npos) << depth;
    EXPECT_EQ(f16.warning.find("wrong") != std::string::npos, depth >= 1200.0f) << f16.warning;
  }
}

TEST_F(StressGlTest, EvsmOverGrowingDepthRanges) {
  // exp(c z) at each format's limit (c = 42 RG32F, 5 RG16F), blurred: the warped far plane exp(2c) and
  // the capped slope term stay finite at every range (run() fails on any NaN or Inf in the moments or
  // the image).
  const Bounds view = make_default_scene().bounds();
  for (float depth : {12.0f, 120.0f, 1200.0f, 12000.0f}) {
    const Scene s = stretched_scene(depth);
    const std::string l = range_label(depth);
    const std::string bias = world_constant("shadow.bias", 0.005, depth);
    for (const char* format : {"RG32F", "RG16F"}) {
      const Outcome o = run((l + " EVSM " + format).c_str(), "finite", 13, s,
                            {std::string("vsm.format=") + format, "light.elevation=90", "vsm.blur_radius=4", bias}, &view);
      // Measured (RG32F): bleeding 0 at 12 and 120; from 1200 on, as with VSM, the minimum variance (in
      // the box's depth units) lets light through every shadow (leak 0.66 at 1200, 1.0 at 12000).
      if (depth <= 120.0f && std::string(format) == "RG32F") {
        EXPECT_LE(o.metrics.acne_rate, 0.005) << depth;
        EXPECT_LE(o.metrics.bleeding_rate, 0.01) << depth;
      }
    }
  }
}

TEST_F(StressGlTest, BlurRadiiUpTo64) {
  const Scene s = make_default_scene();
  for (const char* method : {"separable", "fast"}) {
    std::map<std::string, double> error;
    for (const char* radius : {"16", "32", "64"}) {
      const std::string name = std::string("blur r") + radius + " " + method;
      error[radius] = run(name.c_str(), "finite; r32 = r64 at sigma 8", 5, s,
                          {"shadow.map_size=512", std::string("vsm.blur_radius=") + radius, std::string("vsm.blur_sigma=8"),
                           std::string("vsm.blur_method=") + method})
                          .metrics.mae_edge;
    }
    // sigma 8 (the slider's top) puts 3 sigma at 24 texels: radii 32 and 64 add weights below 1e-3.
    EXPECT_NEAR(error["64"], error["32"], 1e-3) << method;
    EXPECT_GT(std::abs(error["16"] - error["32"]), 0.0) << method;
  }
}

TEST_F(StressGlTest, ExtremeBiasAndDelta) {
  const Scene s = make_default_scene();
  const Outcome zero = run("bias 0", "acne everywhere lit at grazing light", 1, s,
                           {"shadow.bias=0", "shadow.slope_bias=0", "light.elevation=10"});
  const Outcome huge = run("bias 0.1 slope 20", "peter-panning: leaks", 1, s, {"shadow.bias=0.1", "shadow.slope_bias=20"});
  EXPECT_GT(zero.metrics.acne_rate, 0.05);
  EXPECT_GT(huge.metrics.leak_rate, 0.02);
  const Outcome d0 = run("delta 0", "bleeding (blurred)", 4, make_stacked_occluders_scene(),
                         {"vsm.bleed_delta=0", "vsm.blur_radius=4", "vsm.blur_sigma=2"});
  const Outcome d9 = run("delta 0.9", "no bleeding, penumbrae gone dark", 4, make_stacked_occluders_scene(),
                         {"vsm.bleed_delta=0.9", "vsm.blur_radius=4", "vsm.blur_sigma=2"});
  EXPECT_GT(d0.metrics.bleeding_rate, 0.01);
  EXPECT_EQ(d9.metrics.bleeding_rate, 0.0);
  const Outcome v = run("min variance 1e-2", "light through thin shadows", 4, make_stacked_occluders_scene(),
                        {"vsm.min_variance=0.01"});
  EXPECT_GT(v.metrics.leak_rate_all + v.metrics.bleeding_rate, d9.metrics.leak_rate_all);
}

TEST_F(StressGlTest, OffsetScaledFlatAndDegenerateScenes) {
  const Scene base = make_default_scene();
  const Outcome plain = run("default", "lab 1's bounds", 1, base, {});
  for (float offset : {1e4f, 1e6f}) {
    char name[64];
    std::snprintf(name, sizeof name, "offset %.0e", static_cast<double>(offset));
    const Outcome o = run(name, "precision loss grows with the offset", 1,
                          transformed(base, glm::translate(glm::mat4(1.0f), glm::vec3(offset))), {});
    // Measured: 1e4 -> 0.0158 (6x the plain 0.0027: float32 positions keep ~1e-3 units), 1e6 -> 0.94.
    if (offset < 1e5f) {
      EXPECT_LT(o.error, 0.05);
    } else {
      EXPECT_GT(o.error, 0.5) << "if this improves, update the README's limits";
    }
  }
  for (float scale : {1e-3f, 1e4f}) {
    char name[64];
    std::snprintf(name, sizeof name, "scale %.0e", static_cast<double>(scale));
    const Outcome o = run(name, "as unscaled (the fit is scale-free)", 1,
                          transformed(base, glm::scale(glm::mat4(1.0f), glm::vec3(scale))), {});
    EXPECT_NEAR(o.error, plain.error, 0.01) << name;
  }
  Scene flat;
  flat.meshes.push_back(make_plane({0, 0, 0}, 5.0f, 5.0f, glm::vec3(0.8f)));
  const Outcome f = run("flat ground only", "all lit: nothing casts", 1, flat, {"light.elevation=90"});
  EXPECT_EQ(f.metrics.acne_rate_all, 0.0);
  const Outcome g = run("flat ground, grazing 1 deg", "all lit", 1, flat, {"light.elevation=1"});
  EXPECT_LE(g.metrics.acne_rate_all, 0.001);
}

// Issue 16 (figures quoted by lab 2's README): the error at any placement is within kPlacementTolerance of
// the origin's with the local origin; without it, 1e6 away, worse by more than kBrokenWithoutLocalOrigin.
constexpr double kPlacementTolerance = 1e-4;
constexpr double kBrokenWithoutLocalOrigin = 0.1;

// With the local origin (scene.local_origin, on by default) every technique renders the scene
// moved 1e3 ... 1e7 units along each axis, or scaled 1e-4 ... 1e5, with the error it has at the origin at
// scale 1 (within 1e-4). A sample of the grid; `shadowlab bench --placement` runs all of it.
TEST_F(StressGlTest, EveryTechniqueMatchesTheOriginAtAnyOffsetAndScale) {
  const std::vector<PlacementPoint> grid = placement_grid(true);
  for (const PlacementTechnique& t : placement_techniques()) {
    const PlacementSweep sweep = sweep_placements(t, grid, 480, 270);
    EXPECT_GT(sweep.origin.graded, 1000.0) << t.name;
    EXPECT_EQ(sweep.non_finite, 0) << t.name;
    for (std::size_t i = 0; i < grid.size(); ++i)
      EXPECT_NEAR(sweep.points[i].error, sweep.origin.error, kPlacementTolerance) << t.name << ", " << grid[i].label;
    std::printf("  %-38s error at the origin %.5f, worst difference over %zu placements %.2e (offsets) %.2e (scales)\n",
                t.name.c_str(), sweep.origin.error, grid.size(), sweep.worst_offset, sweep.worst_scale);
  }
}

// Placement techniques name their lab by slug and the bench finds its labs by what they offer to it (the
// hard shadow, PCF 3x3), never by number: every name resolves, to the lab that teaches it.
TEST(LabsByWhatTheyOffer, PlacementTechniquesAndBenchFiguresFindTheirLabs) {
  for (const PlacementTechnique& t : placement_techniques()) EXPECT_NO_THROW(placement_lab(t)) << t.name;
  EXPECT_THROW(placement_lab({"nothing", "no_such_lab", {}}), std::invalid_argument);
  const std::pair<const char*, const char*> offers[] = {{"hard", "bias_tuning"}, {"pcf 3", "pcf"}};
  for (const auto& [technique, slug] : offers) {
    const Lab* lab = find_lab_offering(technique);
    ASSERT_NE(lab, nullptr) << technique;
    EXPECT_EQ(lab->slug, slug) << technique;
    EXPECT_EQ(find_lab_named(slug), lab);
  }
  EXPECT_EQ(find_lab_offering("no such technique"), nullptr);
}

// The same test fails without the local origin: the teaching toggle's "before" (float32 holds world
// coordinates). Measured: the depth map's error at 1e6 on the diagonal is 0.9 against 0.003 at the origin.
TEST_F(StressGlTest, WithoutTheLocalOriginAFarSceneBreaks) {
  const Scene scene = make_default_scene();
  for (const PlacementTechnique& t : placement_techniques()) {
    if (t.lab != "bias_tuning" && t.lab != "ortho_fit") continue;  // the depth map and the fitted box
    Renderer renderer;
    CheckContext ctx(renderer, placement_lab(t), Impl::Solution, scene, {});
    const PlacementOutcome origin = measure_placement(ctx, t, Placement{}, 480, 270);
    Placement far;
    far.offset = glm::dvec3(-1e6, 1e6, -1e6);
    far.local_origin = false;
    const PlacementOutcome off = measure_placement(ctx, t, far, 480, 270);
    far.local_origin = true;
    const PlacementOutcome on = measure_placement(ctx, t, far, 480, 270);
    std::printf("  %-38s at 1e6: error %.5f without the local origin, %.5f with it, %.5f at the origin\n", t.name.c_str(),
                off.error, on.error, origin.error);
    EXPECT_GT(off.error - origin.error, kBrokenWithoutLocalOrigin) << t.name;
    EXPECT_NEAR(on.error, origin.error, kPlacementTolerance) << t.name;
  }
}

// A model whose own coordinates are far (Scene::origin, as the glTF loader keeps a georeferenced one):
// the renderer adds its origin to the placement, so it renders as at the origin; without the local
// origin it breaks like a moved scene.
TEST_F(StressGlTest, ASceneWithAFarOriginOfItsOwnRendersAsAtTheOrigin) {
  const PlacementTechnique t = placement_techniques().front();
  Scene far = make_default_scene();
  far.origin = glm::dvec3(1e6, -1e6, 1e6);
  const Scene plain = make_default_scene();
  Renderer renderer;
  CheckContext at_origin(renderer, placement_lab(t), Impl::Solution, plain, {});
  const PlacementOutcome reference = measure_placement(at_origin, t, Placement{}, 480, 270);
  CheckContext moved(renderer, placement_lab(t), Impl::Solution, far, {});
  const PlacementOutcome on = measure_placement(moved, t, Placement{}, 480, 270);
  Placement naive;
  naive.local_origin = false;
  const PlacementOutcome off = measure_placement(moved, t, naive, 480, 270);
  std::printf("  scene origin at 1e6: error %.5f (at the origin %.5f), without the local origin %.5f\n", on.error,
              reference.error, off.error);
  EXPECT_NEAR(on.error, reference.error, kPlacementTolerance);
  EXPECT_GT(off.error - reference.error, kBrokenWithoutLocalOrigin);
}

TEST_F(StressGlTest, EmptySceneAndSinglePointRenderWithoutNaN) {
  Scene point;
  Mesh m;
  m.positions = {glm::vec3(1, 2, 3), glm::vec3(1, 2, 3), glm::vec3(1, 2, 3)};  // a triangle of zero area
  m.normals = {glm::vec3(0, 1, 0), glm::vec3(0, 1, 0), glm::vec3(0, 1, 0)};
  m.indices = {0, 1, 2};
  point.meshes.push_back(m);
  const Scene empty;
  for (const Scene* s : {static_cast<const Scene*>(&point), &empty}) {
    for (int lab : {1, 4, 12}) {  // 12: cascades fitted to an empty box and a zero-area one
      Renderer r;
      r.set_scene(*s);
      ASSERT_TRUE(r.set_features(find_lab(lab)->hooks(Impl::Solution)));
      FrameRequest req;
      req.camera = OrbitCamera::framing(s->bounds());
      req.width = 64;
      req.height = 36;
      req.gbuffer = true;
      r.render(lab_params(*find_lab(lab)), req);
      for (float v : r.read_visibility()) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << lab;
      const glm::mat4 vp = r.light_view().view_projection();
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) ASSERT_TRUE(std::isfinite(vp[c][k])) << lab;
    }
  }
}

}  // namespace
}  // namespace shadowlab
