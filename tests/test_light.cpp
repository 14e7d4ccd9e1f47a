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
