// Light maths: directions, the orthonormal basis, the fitted ortho projection, the orbit camera.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/flashlight.h"
#include "core/light.h"

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
  // Near is the nearest corners' depth along the axis (the box top, 7, less a 0.1 % margin), not a tiny
  // default: the top lands just inside the near plane. (Perspective depth changes by 2f/((f-n)n) ~ 0.62 per unit there.)
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

// A perspective near plane is a plane at an axial depth, not a sphere: a caster off the axis at
// Euclidean distance r lies at axial depth r cos(angle), closer than r. Every point of the box that the
// frustum's sides let through must therefore lie between its near and far planes, or it is clipped out
// of the map (and casts no shadow). The light's distance to the box (the rule before issue 36) clips
// such points; the smallest axial depth of the box's corners does not.
struct ClipMiss {
  int tested = 0;  // points of the box inside the frustum's four sides, in front of the light
  int clipped = 0;  // of those, beyond the near or the far plane
  glm::vec3 first{0.0f};
  float first_depth = 0.0f;  // its window depth, z / w (outside [-1, 1])
};

// Tests the box's corners and `samples` points spread through it (a seeded lattice of random points).
ClipMiss clip_misses(const Bounds& box, const glm::mat4& view_projection, int samples, std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec3> points;
  for (int i = 0; i < 8; ++i) points.push_back(box.corner(i));
  for (int i = 0; i < samples; ++i) points.push_back(box.min + glm::vec3(unit(rng), unit(rng), unit(rng)) * box.extent());
  ClipMiss miss;
  for (const glm::vec3& p : points) {
    const glm::vec4 c = view_projection * glm::vec4(p, 1.0f);
    if (!(c.w > 0.0f) || std::abs(c.x) > c.w || std::abs(c.y) > c.w) continue;
    ++miss.tested;
    if (std::abs(c.z) > c.w) {
      if (miss.clipped++ == 0) {
        miss.first = p;
        miss.first_depth = c.z / c.w;
      }
    }
  }
  return miss;
}

// The near plane's distance along the axis, read back from a GL perspective matrix.
float near_of(const glm::mat4& projection) { return projection[3][2] / (projection[2][2] - 1.0f); }

TEST(SpotLight, NearPlaneClipsNothingInsideTheCone) {
  // The review's case (lab-texts-2026-11-27, finding 4): the default scene, a spot 6 units from the
  // box's centre, 60 degrees up, its azimuth toward the sphere, cone 40. The sphere's top lies 23.5
  // degrees off the axis, at axial depth 3.69, while the light's distance to the box is 3.996.
  const Bounds scene = make_default_scene().bounds();
  const glm::vec3 centre = scene.center();
  const glm::vec3 toward_sphere = glm::normalize(glm::vec3(1, 0, -1));
  const float elevation = glm::radians(60.0f);
  const glm::vec3 position = centre + 6.0f * (std::cos(elevation) * toward_sphere + glm::vec3(0, std::sin(elevation), 0));
  const glm::vec3 axis = glm::normalize(centre - position);
  const LightView lv = fit_spot_light(scene, position, axis, 40.0f);
  const glm::vec3 sphere_top(1.8f, 2.4f, -1.8f);
  const float top_depth = glm::dot(sphere_top - position, axis);
  EXPECT_NEAR(top_depth, 3.69f, 0.01f);
  EXPECT_LT(glm::degrees(std::acos(top_depth / glm::distance(sphere_top, position))), 40.0f) << "inside the cone";
  const glm::vec4 top = lv.view_projection() * glm::vec4(sphere_top, 1.0f);
  EXPECT_GE(top.z, -top.w) << "the sphere's top (axial depth " << top_depth << ") is clipped by the near plane at "
                           << near_of(lv.projection);
  EXPECT_LE(near_of(lv.projection), top_depth);

  // Spots all around the box, near it and far from it, above and below, each aimed near the centre
  // with its own cone: no point of the box inside the frustum's sides is clipped.
  std::mt19937 rng(36);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  const float radius = 0.5f * glm::length(scene.extent());
  int tested = 0;
  for (int i = 0; i < 300; ++i) {
    const glm::vec3 from = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::vec3 light = centre + radius * (0.6f + 2.4f * unit(rng)) * from;
    const glm::vec3 aim = centre + 0.3f * radius * glm::vec3(gauss(rng), gauss(rng), gauss(rng));
    const float cone = 10.0f + 60.0f * unit(rng);
    const LightView spot = fit_spot_light(scene, light, glm::normalize(aim - light), cone);
    const ClipMiss miss = clip_misses(scene, spot.view_projection(), 400, rng);
    tested += miss.tested;
    EXPECT_EQ(miss.clipped, 0) << "spot at (" << light.x << ", " << light.y << ", " << light.z << "), cone " << cone
                               << ", near " << near_of(spot.projection) << ": " << miss.clipped << " of " << miss.tested
                               << " points clipped, first (" << miss.first.x << ", " << miss.first.y << ", "
                               << miss.first.z << ") at window depth " << miss.first_depth;
  }
  EXPECT_GT(tested, 10000) << "enough of the box inside the cones to mean something";
}

TEST(SpotLight, NearPlaneIsTheNearestCornerAlongTheAxis) {
  // Conservative but not wasteful: with the whole box in front of the light, near is its nearest
  // corner's axial depth (less the 0.1 % margin), so some corner lands just inside the near plane.
  const Bounds scene = make_default_scene().bounds();
  const glm::vec3 position(7, 5, 6), axis = glm::normalize(scene.center() - position);
  const LightView lv = fit_spot_light(scene, position, axis, 45.0f);
  float nearest = 1e30f;
  for (int i = 0; i < 8; ++i) nearest = std::min(nearest, glm::dot(scene.corner(i) - position, axis));
  EXPECT_NEAR(near_of(lv.projection), 0.999f * nearest, 1e-4f * nearest);
  // A corner behind the light's plane (a spot low beside the box, looking across it): nothing safe can
  // be said about the nearest depth in the cone, so near falls back to far / 1000.
  const glm::vec3 beside(7, 0.5f, 0), across = glm::normalize(glm::vec3(-1, 0, 1));
  const LightView low = fit_spot_light(scene, beside, across, 45.0f);
  const float far_plane = low.projection[3][2] / (low.projection[2][2] + 1.0f);
  EXPECT_NEAR(near_of(low.projection), far_plane / 1000.0f, 1e-4f * far_plane / 1000.0f);
}

TEST(PointLight, NearPlaneClipsNothingOnAnyFace) {
  // A cube face sees a point at axial depth max(|dx|, |dy|, |dz|) (the face is the largest component),
  // down to D / sqrt(3) for a point at Euclidean distance D. A light outside a corner of the box: the
  // box's nearest corner (5, 1, 5) lies 45 degrees off the +X and -Z faces' axes, at axial depth 3,
  // while the light's distance to the box is 4.24.
  std::mt19937 rng(36);
  const glm::vec3 corner_light(8, 1, 8);
  const CubeLightViews corner = point_light_views(unit_scene(), corner_light);
  EXPECT_LE(corner.near_plane, 3.0f);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  const Bounds scene = unit_scene();
  const float radius = 0.5f * glm::length(scene.extent());
  std::vector<glm::vec3> lights = {corner_light, {0, 1, 0}, {0, 10, 0}, {6, 4, 6}, {-5.5f, -1, 5.5f}};
  for (int i = 0; i < 100; ++i)
    lights.push_back(scene.center() + radius * (0.3f + 2.7f * unit(rng)) *
                                          glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng))));
  int tested = 0;
  for (const glm::vec3& light : lights) {
    const CubeLightViews cube = point_light_views(scene, light);
    for (int f = 0; f < 6; ++f) {
      const ClipMiss miss = clip_misses(scene, cube.projection * cube.view[f], 400, rng);
      tested += miss.tested;
      EXPECT_EQ(miss.clipped, 0) << "point light at (" << light.x << ", " << light.y << ", " << light.z << "), face "
                                 << f << ", near " << cube.near_plane << ": " << miss.clipped << " of " << miss.tested
                                 << " points clipped, first (" << miss.first.x << ", " << miss.first.y << ", "
                                 << miss.first.z << ") at window depth " << miss.first_depth;
    }
  }
  EXPECT_GT(tested, 20000);
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

// Lab 15's node: a rigid transform at its place on the circle whose -Z aims at the box's centre, with a
// basis even straight above the centre (flashlight.radius 0: pointing straight down, where a lookAt with
// up = +Y is NaN); the flashlight's view, lab 15's solution, is fit_spot_light from the node's origin
// along its -Z, and the frame's light is placed with it.
TEST(FlashlightNode, RigidOnItsCircleAndStraightDown) {
  Bounds box;
  box.extend(glm::vec3(-4, 0, -3));
  box.extend(glm::vec3(6, 2, 5));
  const float half_diagonal = 0.5f * glm::length(box.extent());
  ParamSet params(flashlight_param_specs());
  for (const double phase : {0.0, 90.0, 200.0, 333.0}) {
    for (const char* radius : {"0.9", "0"}) {
      params.set("flashlight.phase", phase);
      params.set_from_string("flashlight.radius", radius);
      const glm::mat4 node = flashlight_node_to_world(params, box, glm::mat4(1.0f));
      const glm::mat3 r(node);
      const glm::mat3 rtr = glm::transpose(r) * r;
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(rtr[c][k], c == k ? 1.0f : 0.0f, 1e-5f) << "phase " << phase << " radius " << radius;
      EXPECT_NEAR(glm::determinant(r), 1.0f, 1e-5f);
      const glm::vec3 position(node[3]), axis = -glm::vec3(node[2]);
      EXPECT_NEAR(glm::distance(glm::normalize(box.center() - position), axis), 0.0f, 1e-5f) << "aims at the centre";
      const glm::vec2 out(position.x - box.center().x, position.z - box.center().z);
      EXPECT_NEAR(glm::length(out), std::stof(radius) * half_diagonal, 1e-4f);
      if (std::string(radius) == "0") {
        EXPECT_NEAR(glm::distance(axis, glm::vec3(0, -1, 0)), 0.0f, 1e-6f) << "straight down";
      }
      const LightView fitted = flashlight_view(node, 28.0f, box), spot = fit_spot_light(box, position, axis, 28.0f);
      const FrameLight light = flashlight_light(params, box, glm::mat4(1.0f));
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) {
          ASSERT_TRUE(std::isfinite(fitted.view[c][k]) && std::isfinite(fitted.projection[c][k]));
          EXPECT_NEAR(fitted.view[c][k], spot.view[c][k], 1e-5f);
          EXPECT_NEAR(fitted.projection[c][k], spot.projection[c][k], 1e-5f);
          EXPECT_NEAR(light.view.view_projection()[c][k], spot.view_projection()[c][k], 1e-5f);
        }
    }
  }
}

}  // namespace
}  // namespace shadowlab
