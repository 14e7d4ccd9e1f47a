// Headless GL tests of variance shadow maps (labs 3-5): the moments targets exist only for labs that
// use them, the moments and blur passes run only when their inputs change, radius 0 blurs nothing and
// allocates nothing, no NaN or Inf reaches the moments or the lit output, the remap view tints only
// where the remap acts, and each lab's check passes with its solution and fails with its exercise.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "labs/vsm_features.h"
#include "renderer/gl_objects.h"
#include "renderer/moments_pass.h"
#include "renderer/msm_pass.h"
#include "renderer/renderer.h"
#include "core/vsm_params.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class VsmTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    for (const auto& spec : vsm_param_specs()) params.declare(spec);
    params.apply_assignment("view.debug_quad=false");
  }
  static Features moments_hooks() {
    Features hooks;
    hooks.technique = ShadowTechnique::Moments;
    return hooks;
  }
  FrameRequest request(bool gbuffer = false, int width = 320, int height = 180) const {
    FrameRequest req;
    req.camera = OrbitCamera::framing(scene.bounds());
    req.width = width;
    req.height = height;
    req.gbuffer = gbuffer;
    return req;
  }
  Scene scene = make_default_scene();
  ParamSet params{renderer_param_specs()};
};

std::size_t count_non_finite(const std::vector<float>& values) {
  std::size_t n = 0;
  for (float v : values) n += !std::isfinite(v);
  return n;
}

TEST_F(VsmTest, MomentsTargetsExistOnlyWhileALabUsesThem) {
  Renderer r;
  r.set_scene(scene);
  r.render(params, request());
  EXPECT_EQ(r.moments_targets().size, 0) << "a depth lab allocates no moments texture";
  const int depth_textures = live_gl_objects(GlKind::Texture);

  ASSERT_TRUE(r.set_features(moments_hooks())) << r.shader_error();
  r.render(params, request());
  const MomentsTargetInfo info = r.moments_targets();
  EXPECT_EQ(info.size, 1024);
  EXPECT_EQ(info.internal_format, GL_RG32F);
  EXPECT_EQ(info.min_filter, GL_LINEAR);
  EXPECT_EQ(info.mag_filter, GL_LINEAR);
  EXPECT_EQ(info.depth_internal_format, GL_DEPTH_COMPONENT24);
  EXPECT_EQ(info.depth_attachment_type, GL_RENDERBUFFER);
  EXPECT_FALSE(info.blur_target);
  // The moments texture replaces the depth texture: the same number of textures.
  EXPECT_EQ(live_gl_objects(GlKind::Texture), depth_textures);
  EXPECT_EQ(r.stats().moments_passes, 1);

  params.apply_assignment("vsm.format=RG16F");
  r.render(params, request());
  EXPECT_EQ(r.moments_targets().internal_format, GL_RG16F);

  ASSERT_TRUE(r.set_features({}));
  r.render(params, request());
  EXPECT_EQ(r.moments_targets().size, 0) << "back to a depth lab: the moments targets are gone";
  EXPECT_EQ(live_gl_objects(GlKind::Texture), depth_textures);
}

TEST_F(VsmTest, RadiusZeroRunsNoBlurPassAndAllocatesNothing) {
  Renderer r;
  r.set_scene(scene);
  ASSERT_TRUE(r.set_features(moments_hooks())) << r.shader_error();
  FrameRequest req = request();
  r.render(params, req);
  const int textures = live_gl_objects(GlKind::Texture);
  EXPECT_EQ(r.stats().blur_passes, 0);
  EXPECT_FALSE(r.moments_targets().blur_target);

  params.apply_assignment("vsm.blur_radius=3");
  r.render(params, req);
  EXPECT_EQ(r.stats().blur_passes, 2) << "X and Y";
  EXPECT_TRUE(r.moments_targets().blur_target);
  EXPECT_EQ(live_gl_objects(GlKind::Texture), textures + 1) << "one ping-pong texture";
  bool timed_x = false, timed_y = false;
  for (const auto& p : r.stats().passes) {
    timed_x = timed_x || (p.name == "blur_x" && p.gpu_ms > 0.0);
    timed_y = timed_y || (p.name == "blur_y" && p.gpu_ms > 0.0);
  }
  EXPECT_TRUE(timed_x && timed_y) << r.stats().to_json().dump();

  params.apply_assignment("vsm.blur_radius=0");
  r.render(params, req);
  EXPECT_EQ(r.stats().blur_passes, 2) << "radius 0: no further pass";
  EXPECT_FALSE(r.moments_targets().blur_target);
  EXPECT_EQ(live_gl_objects(GlKind::Texture), textures) << "the ping-pong texture is freed again";
}

TEST_F(VsmTest, MomentsAndBlurRunOnlyWhenTheirInputsChange) {
  Renderer r;
  r.set_scene(scene);
  ASSERT_TRUE(r.set_features(moments_hooks())) << r.shader_error();
  params.apply_assignment("vsm.blur_radius=2");
  FrameRequest req = request();
  for (int i = 0; i < 4; ++i) {
    req.camera.yaw_deg += 10.0f;  // the camera moves: nothing the shadow passes read changed
    r.render(params, req);
  }
  EXPECT_EQ(r.stats().moments_passes, 1);
  EXPECT_EQ(r.stats().blur_passes, 2);
  params.apply_assignment("vsm.min_variance=0.0001");  // read by the lit pass only
  params.apply_assignment("vsm.bleed_delta=0.3");
  r.render(params, req);
  EXPECT_EQ(r.stats().moments_passes, 1);
  params.apply_assignment("vsm.blur_sigma=1.5");  // the blur's input: moments and blur again
  r.render(params, req);
  EXPECT_EQ(r.stats().moments_passes, 2);
  EXPECT_EQ(r.stats().blur_passes, 4);
  params.apply_assignment("light.azimuth=120");
  r.render(params, req);
  EXPECT_EQ(r.stats().moments_passes, 3);
  EXPECT_EQ(r.stats().blur_passes, 6);
  EXPECT_EQ(r.stats().shadow_passes, 3);
}

TEST_F(VsmTest, NoNanOrInfInMomentsOrLitOutput) {
  Renderer r;
  // Every lab's exercise and solution, both formats, with and without blur, under a steep, a grazing
  // and a straight-down light (flat receivers with zero slope: the variance cancels to 0 there).
  for (int number : {3, 4, 5, 13}) {  // 13: EVSM, c at each format's limit (42 RG32F, 5 RG16F)
    const Lab& lab = *find_lab(number);
    for (Impl impl : {Impl::Exercise, Impl::Solution}) {
      ASSERT_TRUE(r.set_features(lab.hooks(impl))) << r.shader_error();
      r.set_scene(number == 4 ? make_stacked_occluders_scene() : scene);
      for (const char* format : {"RG32F", "RG16F"}) {
        for (const char* radius : {"0", "4"}) {
          for (const char* elevation : {"50", "8", "90"}) {
            params.apply_assignment(std::string("vsm.format=") + format);
            params.apply_assignment(std::string("vsm.blur_radius=") + radius);
            params.apply_assignment(std::string("light.elevation=") + elevation);
            params.apply_assignment("view.debug_quad=true");
            r.render(params, request(true, 160, 90));
            const std::string where = "lab " + std::to_string(number) + " " + impl_name(impl) + " " + format +
                                      " radius " + radius + " elevation " + elevation;
            int size = 0;
            EXPECT_EQ(count_non_finite(r.read_moments(&size)), 0u) << where;
            const std::vector<float> vis = r.read_visibility();
            EXPECT_EQ(count_non_finite(vis), 0u) << where;
            for (float v : vis) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << where << ": visibility " << v;
          }
        }
      }
    }
  }
}

TEST_F(VsmTest, FirstMomentIsThePlainDepthAndBackgroundTheClearValue) {
  Renderer r;
  r.set_scene(scene);
  params.apply_assignment("shadow.depth_format=32F");
  params.apply_assignment("shadow.map_size=512");
  r.render(params, request());
  int n = 0;
  const std::vector<float> depth = r.read_shadow_depth(&n);
  ASSERT_TRUE(r.set_features(moments_hooks())) << r.shader_error();
  r.render(params, request());
  int m = 0;
  const std::vector<float> moments = r.read_moments(&m);
  ASSERT_EQ(n, m);
  std::size_t background = 0;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    ASSERT_NEAR(moments[2 * i], depth[i], 1e-5) << "texel " << i;
    ASSERT_GE(moments[2 * i + 1], moments[2 * i] * moments[2 * i]) << "texel " << i << ": negative variance";
    if (depth[i] >= 1.0f) {
      ++background;
      ASSERT_EQ(moments[2 * i], kMomentsClear[0]);
      ASSERT_EQ(moments[2 * i + 1], kMomentsClear[1]);
    }
  }
  EXPECT_GT(background, 0u);
  // The moments pass's own depth renderbuffer holds the same depths, to D24 precision.
  int d = 0;
  const std::vector<float> d24 = r.read_shadow_depth(&d);
  ASSERT_EQ(d, n);
  for (std::size_t i = 0; i < depth.size(); ++i) ASSERT_NEAR(d24[i], depth[i], 1.0 / (1 << 23)) << "texel " << i;
}

TEST_F(VsmTest, RemapViewTintsOnlyTheColourAndOnlyWhereTheRemapActs) {
  scene = make_stacked_occluders_scene();
  Renderer r;
  r.set_scene(scene);
  ASSERT_TRUE(r.set_features(find_lab(4)->hooks(Impl::Solution))) << r.shader_error();
  params.apply_assignment("vsm.blur_radius=4");
  params.apply_assignment("vsm.blur_sigma=2");
  r.render(params, request(true));
  const auto plain = r.read_color();
  const auto vis = r.read_visibility();
  params.apply_assignment("vsm.show_remap=true");
  r.render(params, request(true));
  const auto tinted = r.read_color();
  EXPECT_EQ(r.read_visibility(), vis) << "the view must not change the G-buffer";
  std::size_t changed = 0;
  for (std::size_t i = 0; i < plain.size(); i += 4) changed += plain[i] != tinted[i] || plain[i + 2] != tinted[i + 2];
  EXPECT_GT(changed, 20u) << "the remap acts around the stacked occluders' shadows";
  EXPECT_LT(changed, plain.size() / 4 / 5) << "but not over most of the picture";
  // With delta = 0 there is nothing to show.
  params.apply_assignment("vsm.bleed_delta=0");
  params.apply_assignment("shadow.bias=0");
  r.render(params, request(true));
  params.apply_assignment("vsm.show_remap=false");
  const auto with_view = r.read_color();
  r.render(params, request(true));
  EXPECT_EQ(r.read_color(), with_view);
}

TEST_F(VsmTest, NoGlObjectsAliveAfterShutdown) {
  const int before = live_gl_objects();
  {
    Renderer r;
    r.set_scene(scene);
    ASSERT_TRUE(r.set_features(find_lab(5)->hooks(Impl::Solution))) << r.shader_error();
    params.apply_assignment("vsm.blur_radius=2");
    params.apply_assignment("vsm.show_remap=true");
    params.apply_assignment("view.debug_quad=true");
    r.render(params, request());
    params.apply_assignment("shadow.map_size=256");
    r.render(params, request());
  }
  EXPECT_EQ(live_gl_objects(), before);
}

// The checks themselves: the solution passes, the stock exercise fails (as `shadowlab check` grades).
CheckResult run_check(int number, Impl impl, const std::vector<std::string>& assignments = {}) {
  const Lab& lab = *find_lab(number);
  Renderer renderer;
  const Scene scene = make_default_scene();
  CheckContext ctx(renderer, lab, impl, scene, {});
  ctx.assignments = assignments;
  CheckResult result;
  lab.check(ctx, result);
  return result;
}

std::string failed_criteria(const CheckResult& r) {
  std::string out = r.error;
  for (const auto& c : r.criteria)
    if (!c.passed()) out += c.metric + "=" + std::to_string(c.value) + " ";
  return out;
}

TEST_F(VsmTest, Lab3SolutionPassesExerciseFails) {
  const CheckResult solution = run_check(3, Impl::Solution);
  EXPECT_TRUE(solution.passed()) << failed_criteria(solution);
  EXPECT_FALSE(run_check(3, Impl::Exercise).passed());
}

TEST_F(VsmTest, Lab4SolutionPassesExerciseAndDeltaZeroFail) {
  const CheckResult solution = run_check(4, Impl::Solution);
  EXPECT_TRUE(solution.passed()) << failed_criteria(solution);
  EXPECT_FALSE(run_check(4, Impl::Exercise).passed());
  const CheckResult no_remap = run_check(4, Impl::Solution, {"vsm.bleed_delta=0"});
  EXPECT_FALSE(no_remap.passed()) << "delta = 0 leaves the bleeding in";
}

TEST_F(VsmTest, EvsmStoresTheWarpedDepthWithTheExponentClampedForTheFormat) {
  ParamSet p = lab_params(*find_lab(13));
  p.set("view.debug_quad", 0.0);
  EXPECT_EQ(evsm_exponent(p), 42.0f);
  p.apply_assignment("vsm.format=RG16F");
  EXPECT_EQ(evsm_exponent(p), kEvsmMaxExponentRG16F) << "c is clamped to the half-float range";
  p.apply_assignment("vsm.warp=none");
  EXPECT_EQ(evsm_exponent(p), 0.0f) << "no warp: plain VSM";
  p.apply_assignment("vsm.warp=exponential");
  for (const char* format : {"RG32F", "RG16F"}) {
    p.apply_assignment(std::string("vsm.format=") + format);
    const float c = evsm_exponent(p);
    Renderer r;
    r.set_scene(scene);
    ASSERT_TRUE(r.set_features(find_lab(13)->hooks(Impl::Solution))) << r.shader_error();
    r.render(p, request());
    int size = 0, depth_size = 0;
    const std::vector<float> moments = r.read_moments(&size);
    const std::vector<float> depth = r.read_shadow_depth(&depth_size);
    ASSERT_EQ(size, depth_size);
    const float cn = evsm_exponents(p).y;
    const std::array<float, 4> clear = moments_clear(c, cn);
    // The negative warp's pair, w- = -exp(-c- z), in the texture's last two channels.
    const auto* pass = dynamic_cast<const MomentsPass*>(r.shadow_pass());
    ASSERT_NE(pass, nullptr);
    const std::vector<float> rgba = read_pixels(pass->framebuffer(), GL_COLOR_ATTACHMENT0, size, size, GL_RGBA, 4);
    long covered = 0, wrong = 0;
    for (std::size_t i = 0; i < depth.size(); ++i) {
      const float w = moments[2 * i], w2 = moments[2 * i + 1];
      const float stored = std::string(format) == "RG16F" ? 0x1p-11f : 0.0f;  // half floats round the clear value
      // Below the smallest normal half (6.1e-5: exp(-2c-) at the far plane is 4.5e-5) a half keeps steps of 2^-24.
      const float subnormal = std::string(format) == "RG16F" ? 0x1p-24f : 0.0f;
      const float n = rgba[4 * i + 2], n2 = rgba[4 * i + 3];
      if (depth[i] >= 1.0f) {  // background: the warped far plane
        ASSERT_LE(std::abs(w - clear[0]), stored * clear[0]) << format;
        ASSERT_LE(std::abs(w2 - clear[1]), stored * clear[1]) << format;
        ASSERT_LE(std::abs(n - clear[2]), stored * -clear[2]) << format;
        ASSERT_LE(std::abs(n2 - clear[3]), std::max(stored * clear[3], subnormal)) << format;
        continue;
      }
      ++covered;
      // The negative warp of the same depth (RGBA16F: 2^-11 relative; subnormal halves below 6.1e-5 keep less,
      // so compared there only where -w- is a normal half).
      const double nz = -std::log(-static_cast<double>(n)) / cn;
      if (std::string(format) == "RG32F" || -n > 6.2e-5f) wrong += !(std::abs(nz - depth[i]) <= (std::string(format) == "RG16F" ? 1e-3 : 1e-5));
      wrong += !(n2 >= n * n * (1.0f - 1e-3f) - subnormal && n2 <= 2.0f * n * n * (1.0f + 1e-3f) + subnormal);
      // The first moment is exp(c z) of the stored depth: back in depth units within the format's
      // precision (RG16F: 2^-11 relative, 4.9e-4 / c in z).
      const double z = std::log(static_cast<double>(w)) / c;
      wrong += !(std::abs(z - depth[i]) <= (std::string(format) == "RG16F" ? 1e-3 : 1e-5));
      wrong += !(w2 >= w * w * (1.0f - 1e-3f) && w2 <= 2.0f * w * w * (1.0f + 1e-3f));
    }
    EXPECT_GT(covered, 1000) << format;
    EXPECT_EQ(wrong, 0) << format;
  }
}

TEST_F(VsmTest, Lab13SolutionPassesExerciseFails) {
  const CheckResult solution = run_check(13, Impl::Solution);
  EXPECT_TRUE(solution.passed()) << failed_criteria(solution);
  EXPECT_FALSE(run_check(13, Impl::Exercise).passed()) << "the stock exercise is VSM: it bleeds as much";
}

// Lab 14 measures MSM against VSM from the shared factory (labs/vsm_features.h), not through lab 4: the
// factory's features are lab 4's solution's (technique and shader files), so lab 14's figures are the same.
TEST(VsmFeatures, TheSharedVsmFeatureSetIsLab4sSolution) {
  const Features shared = vsm_features();
  const Features lab4 = find_lab(4)->hooks(Impl::Solution);
  EXPECT_EQ(shared.technique, lab4.technique);
  EXPECT_EQ(shared.includes, lab4.includes);
  EXPECT_EQ(shared.includes.at("lab/visibility.glsl"), kVsmVisibility);
}

TEST_F(VsmTest, MsmStoresFourPowerMomentsAndStaysFinite) {
  // Lab 14's pass: RGBA32F moments (z, z^2, z^3, z^4) of the stored depth, the background the far
  // plane's (1, 1, 1, 1); the Hamburger bound finite and in [0, 1] under steep, grazing and straight-down
  // lights, with the solution and with the stock exercise (Chebyshev's bound on the first two moments).
  const Lab& lab = *find_lab(14);
  ParamSet p = lab_params(lab);
  p.set("view.debug_quad", 0.0);
  for (Impl impl : {Impl::Solution, Impl::Exercise}) {
    Renderer r;
    r.set_scene(scene);
    ASSERT_TRUE(r.set_features(lab.hooks(impl))) << r.shader_error();
    for (const char* elevation : {"50", "8", "90"}) {
      p.apply_assignment(std::string("light.elevation=") + elevation);
      r.render(p, request(true, 160, 90));
      const std::vector<float> vis = r.read_visibility();
      for (float v : vis) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << impl_name(impl) << " elevation " << elevation << ": " << v;
    }
    if (impl == Impl::Exercise) continue;
    int size = 0;
    const std::vector<float> depth = r.read_shadow_depth(&size);
    ASSERT_GT(size, 0);
    const auto* pass = dynamic_cast<const MsmPass*>(r.shadow_pass());
    ASSERT_NE(pass, nullptr);
    const std::vector<float> m = pass->read_moments();
    ASSERT_EQ(m.size(), depth.size() * 4);
    long covered = 0, wrong = 0;
    for (std::size_t i = 0; i < depth.size(); ++i) {
      const double z = m[4 * i];
      if (depth[i] >= 1.0f) {
        wrong += !(m[4 * i] == 1.0f && m[4 * i + 1] == 1.0f && m[4 * i + 2] == 1.0f && m[4 * i + 3] == 1.0f);
        continue;
      }
      ++covered;
      wrong += !(std::abs(z - depth[i]) <= 1e-6);  // 24-bit depth against the float moment
      for (int k = 1; k < 4; ++k) wrong += !(std::abs(m[4 * i + k] - std::pow(z, k + 1)) <= 1e-6);
    }
    EXPECT_GT(covered, 1000);
    EXPECT_EQ(wrong, 0);
  }
}

TEST_F(VsmTest, Lab14SolutionPassesExerciseFails) {
  const CheckResult solution = run_check(14, Impl::Solution);
  EXPECT_TRUE(solution.passed()) << failed_criteria(solution);
  EXPECT_FALSE(run_check(14, Impl::Exercise).passed()) << "two moments are not enough for the Hamburger bound";
}

TEST_F(VsmTest, Lab5SolutionPassesExerciseFails) {
  const CheckResult solution = run_check(5, Impl::Solution);
  EXPECT_TRUE(solution.passed()) << failed_criteria(solution);
  EXPECT_FALSE(run_check(5, Impl::Exercise).passed());
}

}  // namespace
}  // namespace shadowlab
