// Light maths: directions, the orthonormal basis, the fitted ortho projection, the orbit camera.
#include <gtest/gtest.h>

#include <random>

#include "renderer/light.h"

namespace shadowlab {
namespace {

TEST(Direction, AnglesMapToUnitVectors) {
  EXPECT_NEAR(glm::distance(direction_from_angles(0, 90), glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(direction_from_angles(0, 0), glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(direction_from_angles(90, 0), glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
}

// The caster cull's test: a box is outside a light's volume only when it is beyond one clip plane.
TEST(ClipVolume, BoxesOutsideAnOrthoBoxAndASpotFrustum) {
  Bounds scene;
  scene.extend(glm::vec3(-5, 0, -5));
  scene.extend(glm::vec3(5, 2, 5));
  const glm::mat4 ortho = fit_light_ortho(scene, glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f))).view_projection();
  auto box = [](glm::vec3 lo, glm::vec3 hi) {
    Bounds b;
    b.extend(lo);
    b.extend(hi);
    return b;
  };
  EXPECT_FALSE(box_outside_clip_volume(scene, ortho)) << "the fitted box holds the whole scene";
  EXPECT_FALSE(box_outside_clip_volume(box({-1, 0, -1}, {1, 1, 1}), ortho));
  EXPECT_FALSE(box_outside_clip_volume(box({4, 1, 4}, {9, 3, 9}), ortho)) << "straddling a side";
  EXPECT_TRUE(box_outside_clip_volume(box({40, 0, 40}, {41, 1, 41}), ortho)) << "far to the side";
  EXPECT_TRUE(box_outside_clip_volume(Bounds{}, ortho)) << "an empty box";
  // A spot 10 above the origin looking down with a 20-degree half-angle covers |x| < 3.6 at the ground.
  const LightView spot = fit_spot_light(scene, glm::vec3(0, 10, 0), glm::vec3(0, -1, 0), 20.0f);
  const glm::mat4 vp = spot.view_projection();
  EXPECT_FALSE(box_outside_clip_volume(box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}), vp));
  EXPECT_FALSE(box_outside_clip_volume(box({3, 0, -0.5f}, {4, 1, 0.5f}), vp)) << "across the cone's edge";
  EXPECT_TRUE(box_outside_clip_volume(box({4.5f, 0, -0.5f}, {5, 1, 0.5f}), vp)) << "outside the cone";
  EXPECT_TRUE(box_outside_clip_volume(box({-1, 11, -1}, {1, 12, 1}), vp)) << "behind the light (w < 0)";
}

TEST(Basis, OrthonormalForAxesAndRandomDirections) {
  std::vector<glm::vec3> dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::mt19937 rng(7);
  std::normal_distribution<float> g;
  for (int i = 0; i < 1000; ++i) dirs.push_back(glm::normalize(glm::vec3(g(rng), g(rng), g(rng))));
  for (const auto& z : dirs) {
    const glm::mat3 b = orthonormal_basis(z);
    EXPECT_NEAR(glm::length(b[0]), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(b[1]), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(b[0], b[1]), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(b[0], z), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(b[1], z), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(glm::cross(b[0], b[1]), z), 0.0f, 1e-5f);  // right-handed
  }
}

TEST(FitOrtho, BoxCornersFillClipSpaceStraightDown) {
  Bounds b;
  b.extend(glm::vec3(-2, 0, -1));
  b.extend(glm::vec3(2, 3, 1));
  const LightView lv = fit_light_ortho(b, glm::vec3(0, 1, 0));
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = lv.view_projection() * glm::vec4(b.corner(i), 1.0f);
    lo = glm::min(lo, glm::vec3(c));
    hi = glm::max(hi, glm::vec3(c));
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(lo[a], -1.0f, 1e-5f);
    EXPECT_NEAR(hi[a], 1.0f, 1e-5f);
  }
  // The light is above: the top of the box is nearest (depth -1), the bottom farthest (+1).
  const glm::vec4 top = lv.view_projection() * glm::vec4(0, 3, 0, 1);
  EXPECT_NEAR(top.z, -1.0f, 1e-5f);
}

TEST(FitOrtho, FixedTutorialBoxDegeneratesStraightDown) {
  // lookAt with up = +Y and a light along +Y has no valid basis: the tutorial's matrix has NaNs.
  const LightView lv = fixed_tutorial_ortho(glm::vec3(0, 1, 0));
  bool finite = true;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(lv.view[c][r]);
  EXPECT_FALSE(finite);
}

TEST(OrbitCamera, FramingSeesTheWholeBox) {
  Bounds b;
  b.extend(glm::vec3(-5, 0, -5));
  b.extend(glm::vec3(5, 2, 5));
  const OrbitCamera cam = OrbitCamera::framing(b);
  const glm::mat4 vp = cam.projection(16.0f / 9.0f) * cam.view();
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = vp * glm::vec4(b.corner(i), 1.0f);
    EXPECT_GT(c.w, 0.0f);
    EXPECT_LE(std::abs(c.z / c.w), 1.0f) << "corner " << i << " clipped by near or far";
  }
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

Bounds unit_scene() {
  Bounds b;
  b.extend(glm::vec3(-5, 0, -5));
  b.extend(glm::vec3(5, 3, 5));
  return b;
}

TEST(SpotLight, SeesItsTargetAndFitsNearFar) {
  const glm::vec3 pos(0, 10, 0);
  const LightView lv = fit_spot_light(unit_scene(), pos, glm::vec3(0, -1, 0), 60.0f);
  const glm::vec4 centre = lv.view_projection() * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(centre.x / centre.w, 0.0f, 1e-5f);
  EXPECT_NEAR(centre.y / centre.w, 0.0f, 1e-5f);
  // Every corner of the box lies between near and far (depth inside [-1, 1]).
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = lv.view_projection() * glm::vec4(unit_scene().corner(i), 1.0f);
    EXPECT_GT(c.w, 0.0f);
    EXPECT_LE(std::abs(c.z / c.w), 1.0f) << i;
  }
  // Near is the light's distance to the box top (7, less a 0.1 % margin), not a tiny default: the top
  // lands just inside the near plane. (Perspective depth changes by 2f/((f-n)n) ~ 0.62 per unit there.)
  const glm::vec4 top = lv.view_projection() * glm::vec4(0, 3, 0, 1);
  EXPECT_GT(top.z / top.w, -1.0f);
  EXPECT_LT(top.z / top.w, -0.99f);
}

TEST(SpotLight, StraightDownAndInsideTheBoxStayFinite) {
  for (const glm::vec3& dir : {glm::vec3(0, -1, 0), glm::vec3(0, 1, 0)}) {
    const LightView lv = fit_spot_light(unit_scene(), glm::vec3(0, 1, 0), dir, 45.0f);
    const glm::mat4 m = lv.view_projection();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(m[c][r]));
  }
}

TEST(PointLight, SixFacesCoverEveryDirectionOnce) {
  const glm::vec3 pos(0, 1, 0);
  const CubeLightViews cube = point_light_views(unit_scene(), pos);
  const glm::vec3 probes[] = {{1, 0.2f, 0.1f}, {-1, 0.3f, -0.2f}, {0.1f, 1, 0.2f}, {0.2f, -1, 0.1f}, {0.3f, 0.1f, 1}, {0.1f, -0.2f, -1}};
  for (int f = 0; f < 6; ++f) {
    int seen_by = 0;
    for (int g = 0; g < 6; ++g) {
      const glm::vec4 c = cube.projection * cube.view[g] * glm::vec4(pos + probes[f], 1.0f);
      const bool inside = c.w > 0 && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w;
      seen_by += inside;
      if (inside) {
        EXPECT_EQ(g, f) << "probe " << f << " seen by face " << g;
      }
    }
    EXPECT_EQ(seen_by, 1) << "probe " << f;
  }
  EXPECT_LT(cube.near_plane, 1.0f);
  EXPECT_GT(cube.far_plane, glm::length(glm::vec3(5, 2, 5)));
}

}  // namespace
}  // namespace shadowlab
