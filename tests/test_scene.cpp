// Scene building blocks: bounds, transforms, normals and the built-in scenes.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/scene.h"

namespace shadowlab {
namespace {

// Every triangle's winding normal points the same way as its vertex normals (outward for closed shapes).
void expect_outward_winding(const Mesh& m) {
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const auto a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    const glm::vec3 face = glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
    if (glm::length(face) < 1e-12f) continue;  // the sphere's pole triangles can be degenerate
    EXPECT_GT(glm::dot(face, m.normals[a] + m.normals[b] + m.normals[c]), 0.0f) << m.name << " triangle " << t / 3;
  }
}

TEST(Bounds, EmptyUntilExtended) {
  Bounds b;
  EXPECT_TRUE(b.empty());
  b.extend(glm::vec3(1, 2, 3));
  EXPECT_FALSE(b.empty());
  b.extend(glm::vec3(-1, 0, 5));
  EXPECT_EQ(b.min, glm::vec3(-1, 0, 3));
  EXPECT_EQ(b.max, glm::vec3(1, 2, 5));
  EXPECT_EQ(b.center(), glm::vec3(0, 1, 4));
  EXPECT_EQ(b.corner(0), b.min);
  EXPECT_EQ(b.corner(7), b.max);
  EXPECT_EQ(b.corner(1), glm::vec3(1, 0, 3));
}

TEST(Shapes, BoxAndSphereWindOutward) {
  const Mesh box = make_box({1, 2, 3}, {0.5f, 1.0f, 2.0f}, glm::vec3(1));
  EXPECT_EQ(box.triangle_count(), 12u);
  EXPECT_EQ(box.bounds().min, glm::vec3(0.5f, 1.0f, 1.0f));
  EXPECT_EQ(box.bounds().max, glm::vec3(1.5f, 3.0f, 5.0f));
  expect_outward_winding(box);
  const Mesh sphere = make_sphere({0, 0, 0}, 2.0f, 16, 8, glm::vec3(1));
  expect_outward_winding(sphere);
  for (const auto& p : sphere.positions) EXPECT_NEAR(glm::length(p), 2.0f, 1e-5f);
  const Mesh plane = make_plane({0, 0, 0}, 1, 1, glm::vec3(1));
  expect_outward_winding(plane);
}

TEST(Transform, TranslatesScalesAndKeepsNormalsUnit) {
  Mesh box = make_box({0, 0, 0}, {1, 1, 1}, glm::vec3(1));
  const glm::mat4 t = glm::scale(glm::translate(glm::mat4(1), glm::vec3(10, 0, 0)), glm::vec3(2, 1, 1));
  transform_mesh(box, t);
  EXPECT_EQ(box.bounds().min, glm::vec3(8, -1, -1));
  EXPECT_EQ(box.bounds().max, glm::vec3(12, 1, 1));
  for (const auto& n : box.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  expect_outward_winding(box);
}

TEST(Transform, MirrorKeepsOutwardWinding) {
  Mesh box = make_box({0, 0, 0}, {1, 1, 1}, glm::vec3(1));
  transform_mesh(box, glm::scale(glm::mat4(1), glm::vec3(-1, 1, 1)));
  expect_outward_winding(box);
}

TEST(Normals, ComputedFromFacesWhenMissing) {
  Mesh box = make_box({0, 0, 0}, {1, 1, 1}, glm::vec3(1));
  const auto expected = box.normals;
  box.normals.clear();
  compute_normals(box);
  ASSERT_EQ(box.normals.size(), expected.size());
  // The box's faces have their own vertices, so computed normals equal the flat face normals.
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(glm::dot(box.normals[i], expected[i]), 1.0f, 1e-6f);
}

TEST(DefaultScene, HasTheTeachingCases) {
  const Scene s = make_default_scene();
  std::vector<std::string> names;
  for (const auto& m : s.meshes) names.push_back(m.name);
  for (const char* needed : {"ground", "box", "sphere", "floating slab", "thin plate"})
    EXPECT_NE(std::find(names.begin(), names.end(), needed), names.end()) << needed;
  const Bounds b = s.bounds();
  EXPECT_FLOAT_EQ(b.min.y, 0.0f);
  EXPECT_GT(s.triangle_count(), 100u);
  for (const auto& m : s.meshes) {
    EXPECT_EQ(m.normals.size(), m.positions.size());
    for (auto i : m.indices) EXPECT_LT(i, m.positions.size());
  }
}

}  // namespace
}  // namespace shadowlab
