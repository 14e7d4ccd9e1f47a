// The window's Penumbra error view (app/penumbra_view.h), measured the way the window and
// `render --panel --penumbra` measure: lab 0's hard shadow map against a 3-degree sun is wrong in the
// penumbra on both sides of every edge (too dark outside the true umbra's middle, too light inside), and
// the picture shows both colours; at size 0 there is no penumbra to grade.
#include <gtest/gtest.h>

#include <cstdio>

#include "app/penumbra_view.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/renderer.h"
#include "core/scene.h"
#include "tests/gl_fixture.h"

namespace shadowlab {
namespace {

class PenumbraViewTest : public GlTest {};

struct Tints {
  long too_dark = 0, too_light = 0;
};

// Pixels turned toward the too-dark colour (kDiffAcne) or the too-light one (kDiffLeak), by more than grey.
Tints count_tints(const PenumbraMeasure& m) {
  Tints t;
  for (std::size_t i = 0; i + 3 < m.rgba.size(); i += 4) {
    const int r = m.rgba[i], g = m.rgba[i + 1], b = m.rgba[i + 2];
    const int dr = r - g, db = b - g;
    const int dark_r = kDiffAcne[0] - kDiffAcne[1], dark_b = kDiffAcne[2] - kDiffAcne[1];
    const int light_r = kDiffLeak[0] - kDiffLeak[1], light_b = kDiffLeak[2] - kDiffLeak[1];
    // The tint's direction: the pixel's colour minus its grey, along each diff colour's own.
    if (dr * dark_r + db * dark_b > 40 * 40) ++t.too_dark;
    if (dr * light_r + db * light_b > 40 * 40) ++t.too_light;
  }
  return t;
}

TEST_F(PenumbraViewTest, AHardMapIsShownTooDarkAndTooLightInTheSunsPenumbra) {
  const Lab& lab = *find_lab(0);
  Renderer renderer;
  ASSERT_TRUE(renderer.set_features(lab.hooks(Impl::Solution))) << renderer.shader_error();
  renderer.set_scene(make_default_scene());
  const Oracle oracle(renderer.scene());
  ParamSet params = lab_params(lab);
  const OrbitCamera camera = frame_scene_camera(renderer.scene(), params);

  params.set("light.size", 3.0);
  const PenumbraMeasure sized = measure_penumbra(renderer, params, camera, oracle, 320, 180);
  ASSERT_EQ(sized.rgba.size(), 320u * 180u * 4u);
  EXPECT_TRUE(sized.sun);
  EXPECT_FLOAT_EQ(sized.light_size, 3.0f);
  // Measured at 320 x 180: 173 penumbra pixels, 0.242 error there, 77 drawn too dark and 95 too light.
  ASSERT_GT(sized.metrics.penumbra_pixels, 50u);
  // A hard edge through the penumbra: about half of it on each side (measured 0.22-0.26 at 2 degrees in
  // the checks, tests/test_gl_soft_check.cpp).
  EXPECT_GT(sized.metrics.mae_penumbra, 0.1);
  EXPECT_GT(sized.metrics.too_dark, 0.0);
  EXPECT_GT(sized.metrics.too_light, 0.0);
  const Tints tints = count_tints(sized);
  const long quarter = static_cast<long>(sized.metrics.penumbra_pixels / 4);
  EXPECT_GT(tints.too_dark, quarter);
  EXPECT_GT(tints.too_light, quarter);

  params.set("light.size", 0.0);
  const PenumbraMeasure hard = measure_penumbra(renderer, params, camera, oracle, 320, 180);
  EXPECT_EQ(hard.metrics.penumbra_pixels, 0u);
  EXPECT_LT(hard.metrics.mae, 0.02);  // lab 0's solution against its own hard truth
  EXPECT_LT(count_tints(hard).too_dark + count_tints(hard).too_light, count_tints(sized).too_dark / 4);
  EXPECT_NE(hard.view_key, sized.view_key);
  OrbitCamera moved = camera;
  moved.yaw_deg += 10.0f;
  EXPECT_NE(penumbra_view_key(params, moved), hard.view_key);
  EXPECT_EQ(penumbra_view_key(params, camera), hard.view_key);
  std::printf("penumbra view, 3-degree sun, lab 0's hard map: penumbra %llu px, error there %.3f (too dark %.4f, "
              "too light %.4f overall), %ld / %ld tinted px; %.0f ms\n",
              static_cast<unsigned long long>(sized.metrics.penumbra_pixels), sized.metrics.mae_penumbra,
              sized.metrics.too_dark, sized.metrics.too_light, tints.too_dark, tints.too_light, sized.seconds * 1000.0);
}

}  // namespace
}  // namespace shadowlab
