// The ray-cast oracle and the error metrics, on synthetic G-buffers (no GL): shadows whose footprint is
// known in closed form, the edge band's width, validity rules, exact metric counts and diff colours.
#include "oracle/oracle.h"
#include "oracle/metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace shadowlab {
namespace {

const glm::vec3 kGrey{0.7f};

// A regular grid of points on the ground (y = 0, normal up): pixel (ix, iz) samples the centre of its
// cell of [x0, x1] x [z0, z1]; row iz = 0 is the bottom row (smallest z).
GBuffer ground_grid(int nx, int nz, double x0, double x1, double z0, double z1) {
  GBuffer g;
  g.width = nx;
  g.height = nz;
  const auto n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz);
  g.position.resize(n);
  g.normal.assign(n, glm::vec3(0, 1, 0));
  g.covered.assign(n, 1);
  for (int iz = 0; iz < nz; ++iz) {
    for (int ix = 0; ix < nx; ++ix) {
      const double x = x0 + (ix + 0.5) * (x1 - x0) / nx;
      const double z = z0 + (iz + 0.5) * (z1 - z0) / nz;
      g.position[static_cast<std::size_t>(iz) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(ix)] =
          glm::vec3(static_cast<float>(x), 0.0f, static_cast<float>(z));
    }
  }
  return g;
}

// Signed distance from (x, z) to the rectangle [x0, x1] x [z0, z1]: negative inside.
double rect_distance(double x, double z, double x0, double x1, double z0, double z1) {
  const double dx = std::max(x0 - x, x - x1), dz = std::max(z0 - z, z - z1);
  if (dx <= 0 && dz <= 0) return std::max(dx, dz);
  return std::hypot(std::max(dx, 0.0), std::max(dz, 0.0));
}

std::size_t count_if_pixels(const Truth& t, const std::function<bool(std::size_t)>& pred) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < t.valid.size(); ++i) n += pred(i) ? 1 : 0;
  return n;
}

// 400 x 400 pixels over the 10 x 10 ground: spacing h = 0.025, pixel centres at odd multiples of h/2,
// so no centre lies exactly on a shadow border at a multiple of h.
constexpr int kGrid = 400;
constexpr double kHalf = 5.0;
constexpr double kSpacing = 2 * kHalf / kGrid;

// ---------------------------------------------------------------------------------------------------
// The hand-worked case: a unit box (half-size 1) centred 2 above a 10 x 10 ground, light straight down.
// The shadow is the box's footprint [-1, 1]^2: 4 of the ground's 100 square units.

Scene square_scene() {
  Scene s;
  s.meshes.push_back(make_plane({0, 0, 0}, 5.0f, 5.0f, kGrey));
  s.meshes.push_back(make_box({0, 2, 0}, {1, 1, 1}, kGrey));
  return s;
}

OracleLight light_from_above(float texel_world_size) {
  OracleLight l;
  l.to_light = {0, 1, 0};
  l.image_x = {1, 0, 0};
  l.image_y = {0, 0, 1};
  l.texel_world_size = texel_world_size;
  return l;
}

TEST(Oracle, SquareShadowAreaAndBand) {
  const Oracle oracle(square_scene());
  EXPECT_EQ(oracle.triangle_count(), 2u + 12u);
  EXPECT_GT(oracle.build_seconds(), 0.0);
  const GBuffer g = ground_grid(kGrid, kGrid, -kHalf, kHalf, -kHalf, kHalf);
  const float texel = 0.05f;  // band radius r = 2 texels = 0.1 = 4 pixel spacings
  const double r = 2 * texel;
  const Truth t = oracle.evaluate(g, light_from_above(texel));
  ASSERT_EQ(t.width, kGrid);
  ASSERT_EQ(t.height, kGrid);
  const std::size_t n = g.position.size();
  EXPECT_EQ(count_if_pixels(t, [&](std::size_t i) { return t.valid[i] != 0; }), n);

  // Area: a pixel can be misclassified only if its cell straddles the border, and at most
  // perimeter / h = 8 / 0.025 = 320 cells do: tolerance 320 / 160000 = 0.002 of the area fraction.
  const double shadowed = static_cast<double>(count_if_pixels(t, [&](std::size_t i) { return !t.lit[i]; }));
  const double tolerance = 8.0 * kSpacing / 100.0;
  EXPECT_NEAR(shadowed / static_cast<double>(n), 4.0 / 100.0, tolerance);
  // With these centres the count is in fact exact: 80 x 80 pixels.
  EXPECT_EQ(shadowed, 80.0 * 80.0);

  std::size_t edge = 0, edge_far = 0, interior_near = 0, lit_wrong = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 p = g.position[i];
    const double d = rect_distance(p.x, p.z, -1, 1, -1, 1);
    if (std::abs(d) > kSpacing) lit_wrong += (t.lit[i] != 0) != (d > 0);
    if (!t.interior[i]) {
      ++edge;
      // Every edge pixel lies within 2 texels of the border ...
      if (std::abs(d) > r + 1e-4) ++edge_far;
    } else {
      // ... and along the sides (away from the corners), every pixel closer than r to the border is on an
      // edge: the samples at angles 0, 90, 180, 270 degrees reach exactly r across it.
      const bool along_x_side = std::abs(p.z) < 1 - r && std::abs(std::abs(p.x) - 1) < r - 1e-4;
      const bool along_z_side = std::abs(p.x) < 1 - r && std::abs(std::abs(p.z) - 1) < r - 1e-4;
      if (along_x_side || along_z_side) ++interior_near;
    }
  }
  EXPECT_EQ(lit_wrong, 0u);
  EXPECT_EQ(edge_far, 0u);
  EXPECT_EQ(interior_near, 0u);
  // The band is a stripe of width 2r around the perimeter: about 8 * 0.2 = 1.6 square units = 2560 pixels.
  EXPECT_GT(edge, 2300u);
  EXPECT_LT(edge, 2700u);

  // Rays: one per valid pixel, plus 8 per interior pixel, plus at least one per edge pixel.
  const std::uint64_t interior = n - edge;
  EXPECT_GE(t.rays, n + 8 * interior + edge);
  EXPECT_LE(t.rays, 9 * n);
  EXPECT_GT(t.seconds, 0.0);
}

TEST(Oracle, FixedScreenBandUsesNoExtraRays) {
  const Oracle oracle(square_scene());
  const GBuffer g = ground_grid(kGrid, kGrid, -kHalf, kHalf, -kHalf, kHalf);
  BandSpec band;
  band.fixed_screen_pixels = 3;
  const Truth t = oracle.evaluate(g, light_from_above(0.05f), band);
  const std::size_t n = g.position.size();
  EXPECT_EQ(t.rays, n);
  // Brute force: interior iff no pixel of the other truth within the 7 x 7 square.
  std::size_t mismatches = 0, edge = 0;
  for (int y = 0; y < kGrid; ++y) {
    for (int x = 0; x < kGrid; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kGrid + static_cast<std::size_t>(x);
      bool differs = false;
      for (int dy = -3; dy <= 3; ++dy) {
        for (int dx = -3; dx <= 3; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= kGrid || yy >= kGrid) continue;
          const std::size_t j = static_cast<std::size_t>(yy) * kGrid + static_cast<std::size_t>(xx);
          differs = differs || (t.valid[j] && t.lit[j] != t.lit[i]);
        }
      }
      mismatches += (t.interior[i] != 0) == differs;
      edge += !t.interior[i];
    }
  }
  EXPECT_EQ(mismatches, 0u);
  // The shadowed 80 x 80 block: 3 pixels inside and outside its border are edges: 86^2 - 74^2.
  EXPECT_EQ(edge, 86u * 86u - 74u * 74u);
}

// ---------------------------------------------------------------------------------------------------
// Light at elevation 45 degrees (to_light = (1, 1, 0) / sqrt 2) over a unit box resting on the ground,
// spanning [-1, 1] x [0, 2] x [-1, 1]. A box corner (x, y, z) projects along the light to (x - y, 0, z),
// so the shadow (the box's footprint included) is the hull [-1 - 2, 1 - 0] x [-1, 1] = [-3, 1] x [-1, 1]:
// 8 square units.

TEST(Oracle, TiltedLightFootprintAndStretchedBand) {
  Scene s;
  s.meshes.push_back(make_plane({0, 0, 0}, 5.0f, 5.0f, kGrey));
  s.meshes.push_back(make_box({0, 1, 0}, {1, 1, 1}, kGrey));
  const Oracle oracle(s);
  const GBuffer g = ground_grid(kGrid, kGrid, -kHalf, kHalf, -kHalf, kHalf);
  OracleLight light;
  light.to_light = glm::normalize(glm::vec3(1, 1, 0));
  light.image_x = glm::normalize(glm::vec3(1, -1, 0));
  light.image_y = {0, 0, 1};
  light.texel_world_size = 0.05f;
  const double r = 0.1;
  const Truth t = oracle.evaluate(g, light);
  const std::size_t n = g.position.size();

  const double shadowed = static_cast<double>(count_if_pixels(t, [&](std::size_t i) { return !t.lit[i]; }));
  const double tolerance = 12.0 * kSpacing / 100.0;  // perimeter 12: at most 480 straddling cells
  EXPECT_NEAR(shadowed / static_cast<double>(n), 8.0 / 100.0, tolerance);

  // On the ground, the band circle becomes an ellipse: an image-plane offset r * image_x slides along
  // the light by r onto the ground, landing r * sqrt 2 away in x; image_y offsets stay r in z. In
  // coordinates (x / sqrt 2, z) the ellipse is a circle of radius r again.
  const double k = std::sqrt(2.0);
  std::size_t lit_wrong = 0, edge_far = 0, stretched_edge = 0, stretched_interior = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 p = g.position[i];
    const double d = rect_distance(p.x, p.z, -3, 1, -1, 1);
    if (std::abs(d) > kSpacing) lit_wrong += (t.lit[i] != 0) != (d > 0);
    const double d_scaled = rect_distance(p.x / k, p.z, -3 / k, 1 / k, -1, 1);
    if (!t.interior[i] && std::abs(d_scaled) > r + 1e-4) ++edge_far;
    // Pixels between r and r sqrt 2 from the x = 1 or x = -3 sides: edges only because of the stretch.
    const double dx = std::min(std::abs(p.x - 1.0), std::abs(p.x + 3.0));
    if (std::abs(p.z) < 1 - r && dx > r + 1e-4 && dx < r * k - 1e-4) {
      (t.interior[i] ? stretched_interior : stretched_edge) += 1;
    }
  }
  EXPECT_EQ(lit_wrong, 0u);
  EXPECT_EQ(edge_far, 0u);
  EXPECT_EQ(stretched_interior, 0u);
  EXPECT_GT(stretched_edge, 0u);
}

// ---------------------------------------------------------------------------------------------------
// A point light 6 above the ground over the same floating box (top face at y = 3, half-size 1): by
// similar triangles the top face's shadow is scaled by 6 / (6 - 3) = 2, and it covers the bottom face's
// (scale 6 / 5): the shadow is the square [-2, 2]^2, 16 square units.

TEST(Oracle, PointLightSimilarTriangles) {
  const Oracle oracle(square_scene());
  const GBuffer g = ground_grid(kGrid, kGrid, -kHalf, kHalf, -kHalf, kHalf);
  OracleLight light;
  light.positional = true;
  light.position = {0, 6, 0};
  light.texel_angle = 0.005f;  // band: 2 texels = 0.01 rad
  const double angle = 0.01;
  const Truth t = oracle.evaluate(g, light);
  const std::size_t n = g.position.size();
  EXPECT_EQ(count_if_pixels(t, [&](std::size_t i) { return t.valid[i] != 0; }), n);

  const double shadowed = static_cast<double>(count_if_pixels(t, [&](std::size_t i) { return !t.lit[i]; }));
  const double tolerance = 16.0 * kSpacing / 100.0;
  EXPECT_NEAR(shadowed / static_cast<double>(n), 16.0 / 100.0, tolerance);
  std::size_t lit_wrong = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec3 p = g.position[i];
    const double d = rect_distance(p.x, p.z, -2, 2, -2, 2);
    if (std::abs(d) > kSpacing) lit_wrong += (t.lit[i] != 0) != (d > 0);
  }
  EXPECT_EQ(lit_wrong, 0u);

  // Along the row next to z = 0, the band around the x = 2 border spans the ground points seen from the
  // light within +-0.01 rad of the border's direction: x = 6 tan(atan(2 / 6) -+ 0.01).
  const double border = std::atan(2.0 / 6.0);
  const double band_lo = 6 * std::tan(border - angle), band_hi = 6 * std::tan(border + angle);
  const int row = kGrid / 2;  // z = +h/2
  std::size_t wrong = 0, in_band = 0;
  for (int x = kGrid / 2 + 40; x < kGrid; ++x) {  // x > 1
    const std::size_t i = static_cast<std::size_t>(row) * kGrid + static_cast<std::size_t>(x);
    const double px = g.position[i].x;
    if (std::abs(px - band_lo) < kSpacing / 2 || std::abs(px - band_hi) < kSpacing / 2) continue;
    const bool expect_edge = px > band_lo && px < band_hi;
    in_band += expect_edge;
    wrong += expect_edge == (t.interior[i] != 0);
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_GE(in_band, 4u);  // the band is about 0.13 wide: 5 pixels
}

// ---------------------------------------------------------------------------------------------------

TEST(Oracle, BackFacingAndBackgroundPixelsAreInvalid) {
  const Oracle oracle(square_scene());
  GBuffer g;
  g.width = 3;
  g.height = 2;
  g.position = {{3, 0, 3}, {3, 0, 3}, {3, 0, 3}, {3, 0, 3}, {0, 0, 0}, {3, 0, 3}};
  g.normal = {{0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  g.covered = {1, 1, 1, 0, 1, 1};
  g.position[5] = {std::numeric_limits<float>::quiet_NaN(), 0, 0};
  const Truth t = oracle.evaluate(g, light_from_above(0.05f));
  // 0: faces the light, lit. 1: faces away. 2: grazing (n . l = 0). 3: background. 4: under the box.
  // 5: a non-finite position.
  EXPECT_EQ(t.valid, (std::vector<std::uint8_t>{1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(t.lit, (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 0}));
  EXPECT_EQ(t.interior, (std::vector<std::uint8_t>{1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(t.rays, 2u * 9u);  // invalid pixels cast nothing; both valid ones are interior

  // A point light below the ground: the upward-facing ground is back-facing to it.
  OracleLight below;
  below.positional = true;
  below.position = {0, -4, 0};
  const Truth u = oracle.evaluate(g, below);
  EXPECT_EQ(u.valid, (std::vector<std::uint8_t>{0, 1, 0, 0, 0, 0}));  // only the down-facing normal
  EXPECT_EQ(u.rays, 1u);  // texel_angle 0: no band rays
  // At the light itself the direction is undefined (pixels 0-2), and (0, 0, 0) sees the light level with
  // the ground (n . l = 0): nothing is valid.
  OracleLight at_pixel = below;
  at_pixel.position = {3, 0, 3};
  const Truth w = oracle.evaluate(g, at_pixel);
  EXPECT_EQ(std::count(w.valid.begin(), w.valid.end(), 1), 0);
  EXPECT_EQ(w.rays, 0u);
}

// Grazing pixels (n . l below the limit) join the band in both band modes; they stay valid and keep
// their truth, so the rates over all pixels still see them.
TEST(Oracle, GrazingPixelsJoinTheBand) {
  const Oracle oracle(square_scene());
  GBuffer g;
  g.width = 5;
  g.height = 1;
  // Lit ground, a grazing lit pixel (normal 87 degrees from the light), lit ground, nothing, shadowed
  // ground under the box: with a band of one screen pixel only pixel 1's own angle can put it in the band.
  const float grazing = 0.05f;
  g.position = {{3, 0, 3}, {3.1f, 0, 3}, {3.2f, 0, 3}, {0, 0, 0}, {0, 0, 0}};
  g.normal = {{0, 1, 0}, glm::normalize(glm::vec3(std::sqrt(1 - grazing * grazing), grazing, 0)), {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  g.covered = {1, 1, 1, 0, 1};
  BandSpec band;
  band.fixed_screen_pixels = 1;
  const Truth all = oracle.evaluate(g, light_from_above(0.05f), band);
  EXPECT_EQ(all.interior, (std::vector<std::uint8_t>{1, 1, 1, 0, 1}));
  band.grazing_n_dot_l = 0.1f;
  const Truth t = oracle.evaluate(g, light_from_above(0.05f), band);
  EXPECT_EQ(t.valid, all.valid);
  EXPECT_EQ(t.lit, (std::vector<std::uint8_t>{1, 1, 1, 0, 0}));
  EXPECT_EQ(t.interior, (std::vector<std::uint8_t>{1, 0, 1, 0, 1}));
  // The texel band too: the grazing pixel is in it, the others are as without the limit.
  BandSpec texels;
  const Truth u0 = oracle.evaluate(g, light_from_above(0.05f), texels);
  texels.grazing_n_dot_l = 0.1f;
  const Truth u = oracle.evaluate(g, light_from_above(0.05f), texels);
  EXPECT_EQ(u.lit, u0.lit);
  EXPECT_EQ(u.interior[1], 0);
  for (std::size_t i : {0u, 2u, 4u}) EXPECT_EQ(u.interior[i], u0.interior[i]) << i;
}

TEST(Oracle, OccludedSegment) {
  const Oracle oracle(square_scene());
  const glm::vec3 up(0, 1, 0);
  EXPECT_FALSE(oracle.occluded({0, 0.5f, 0}, up, 0.4f));  // stops short of the box's bottom at y = 1
  EXPECT_TRUE(oracle.occluded({0, 0.5f, 0}, up, 0.6f));
  EXPECT_TRUE(oracle.occluded({0, 0.5f, 0}, up, std::numeric_limits<float>::infinity()));
  EXPECT_FALSE(oracle.occluded({0, 0.5f, 0}, up, 0.0f));
  EXPECT_FALSE(oracle.occluded({3, 0.5f, 0}, up, 100.0f));  // beside the box
  EXPECT_TRUE(oracle.occluded({3, 0.5f, 0}, -up, 1.0f));    // the ground (hit from either side)
}

TEST(Oracle, MeshesThatCastNoShadowDoNotOcclude) {
  Scene s = square_scene();
  s.meshes[1].casts_shadow = false;
  const Oracle oracle(s);
  EXPECT_EQ(oracle.triangle_count(), 2u);
  const GBuffer g = ground_grid(40, 40, -kHalf, kHalf, -kHalf, kHalf);
  const Truth t = oracle.evaluate(g, light_from_above(0.05f));
  EXPECT_EQ(std::count(t.lit.begin(), t.lit.end(), 1), 40 * 40);
}

TEST(Oracle, RejectsBadInput) {
  Scene s = square_scene();
  s.meshes[1].indices[5] = 1000;
  try {
    const Oracle bad(s);
    FAIL() << "an out-of-range index was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("index 1000"), std::string::npos) << e.what();
  }

  const Oracle oracle(square_scene());
  GBuffer g = ground_grid(4, 4, -1, 1, -1, 1);
  g.normal.pop_back();
  EXPECT_THROW((void)oracle.evaluate(g, light_from_above(0.05f)), std::invalid_argument);
  g = ground_grid(4, 4, -1, 1, -1, 1);
  OracleLight zero = light_from_above(0.05f);
  zero.to_light = glm::vec3(0);
  EXPECT_THROW((void)oracle.evaluate(g, zero), std::invalid_argument);
}

TEST(Oracle, EmptySceneAndEmptyImage) {
  const Oracle oracle(Scene{});
  EXPECT_EQ(oracle.triangle_count(), 0u);
  EXPECT_FALSE(oracle.occluded({0, 0, 0}, {0, 1, 0}, 10.0f));
  const Truth t = oracle.evaluate(GBuffer{}, light_from_above(0.05f));
  EXPECT_EQ(t.width, 0);
  EXPECT_TRUE(t.valid.empty());
  EXPECT_EQ(t.rays, 0u);
}

// A small lit, tilted plane 2 x 10^4 away from the origin: G-buffer points interpolated in float lie off
// the plane by about a float ulp of their coordinates (~0.002), more than the scene-relative offset
// (10^-4 x the 1.4 diagonal), so only the position-relative part of the offset keeps them lit.
TEST(Oracle, NoSelfShadowFarFromOrigin) {
  Scene s;
  s.meshes.push_back(make_plane({0, 0, 0}, 0.5f, 0.5f, kGrey));
  const glm::mat4 transform = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(2.0e4f, 3.0e3f, -1.5e4f)), 0.7f,
                                          glm::normalize(glm::vec3(1, 0.3f, 0.5f)));
  transform_mesh(s.meshes[0], transform);
  const Oracle oracle(s);
  const Mesh& m = s.meshes[0];
  GBuffer g;
  g.width = 64;
  g.height = 64;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / 64.0f, v = (static_cast<float>(y) + 0.5f) / 64.0f;
      // Bilinear over the quad's corners, in float as a rasteriser would.
      const glm::vec3 p = (1 - v) * ((1 - u) * m.positions[0] + u * m.positions[1]) +
                          v * ((1 - u) * m.positions[3] + u * m.positions[2]);
      g.position.push_back(p);
      g.normal.push_back(m.normals[0]);
      g.covered.push_back(1);
    }
  }
  OracleLight light;
  light.to_light = glm::normalize(m.normals[0] + 0.8f * glm::vec3(1, 0, 0));
  ASSERT_GT(glm::dot(light.to_light, m.normals[0]), 0.1f);
  const Truth t = oracle.evaluate(g, light);
  EXPECT_EQ(std::count(t.valid.begin(), t.valid.end(), 1), 64 * 64);
  EXPECT_EQ(std::count(t.lit.begin(), t.lit.end(), 1), 64 * 64);
}

OracleLight default_scene_light() {
  OracleLight l;
  l.to_light = glm::normalize(glm::vec3(-0.5f, 1.0f, 0.35f));
  l.image_x = glm::normalize(glm::cross(l.to_light, glm::vec3(0, 0, 1)));
  l.image_y = glm::cross(l.to_light, l.image_x);
  l.texel_world_size = 24.0f / 2048.0f;  // a 2048^2 map over ~24 units
  return l;
}

TEST(Oracle, DeterministicAcrossRuns) {
  const Oracle oracle(make_default_scene());
  const GBuffer g = ground_grid(160, 90, -8, 8, -8, 8);
  const Truth a = oracle.evaluate(g, default_scene_light());
  const Truth b = oracle.evaluate(g, default_scene_light());
  EXPECT_EQ(a.valid, b.valid);
  EXPECT_EQ(a.lit, b.lit);
  EXPECT_EQ(a.interior, b.interior);
  EXPECT_EQ(a.rays, b.rays);
  EXPECT_GT(std::count(a.lit.begin(), a.lit.end(), 0), 0);  // the default scene does shade its ground
}

// ---------------------------------------------------------------------------------------------------
// Metrics on a hand-made truth. Pixels (valid, lit, interior, visibility):
//   0: interior lit, 1.0         correct
//   1: interior lit, 0.25        acne, error 0.75
//   2: interior shadowed, 0.0    correct
//   3: interior shadowed, 0.625  leak and bleeding, error 0.625
//   4: interior shadowed, 0.0625 correct, below the bleeding threshold, error 0.0625
//   5: edge lit, 0.25            acne (edge), error 0.75
//   6: edge shadowed, 0.875      leak (edge), error 0.875
//   7: invalid, 0.875            ignored
//   8: interior shadowed, 0.375  bleeding but not leak, error 0.375
//   9: invalid, NaN              ignored

Truth hand_truth() {
  Truth t;
  t.width = 5;
  t.height = 2;
  t.valid = {1, 1, 1, 1, 1, 1, 1, 0, 1, 0};
  t.lit = {1, 1, 0, 0, 0, 1, 0, 1, 0, 0};
  t.interior = {1, 1, 1, 1, 1, 0, 0, 1, 1, 0};
  return t;
}

const std::vector<float> kHandVisibility = {1.0f,   0.25f,  0.0f,   0.625f, 0.0625f,
                                            0.25f,  0.875f, 0.875f, 0.375f, std::numeric_limits<float>::quiet_NaN()};

TEST(Metrics, ExactRatesOnHandMadeTruth) {
  const Metrics m = compare(hand_truth(), kHandVisibility);
  EXPECT_EQ(m.valid_pixels, 8u);
  EXPECT_EQ(m.interior_lit, 2u);
  EXPECT_EQ(m.interior_shadowed, 4u);
  EXPECT_EQ(m.edge_pixels, 2u);
  EXPECT_DOUBLE_EQ(m.acne_rate, 1.0 / 2.0);
  EXPECT_DOUBLE_EQ(m.leak_rate, 1.0 / 4.0);
  EXPECT_DOUBLE_EQ(m.acne_rate_all, 2.0 / 3.0);   // lit: 0, 1, 5
  EXPECT_DOUBLE_EQ(m.leak_rate_all, 2.0 / 5.0);   // shadowed: 2, 3, 4, 6, 8
  EXPECT_DOUBLE_EQ(m.bleeding_rate, 2.0 / 4.0);   // 3 and 8
  EXPECT_DOUBLE_EQ(m.mae_interior, (0.75 + 0.625 + 0.0625 + 0.375) / 6.0);
  EXPECT_DOUBLE_EQ(m.mae_edge, (0.75 + 0.875) / 2.0);
  EXPECT_DOUBLE_EQ(m.lit_error, (0.0 + 0.75) / 2.0);                      // interior lit: 0, 1
  EXPECT_DOUBLE_EQ(m.shadow_error, (0.0 + 0.625 + 0.0625 + 0.375) / 4.0);  // interior shadowed: 2, 3, 4, 8
}

// A partly wrong answer that never crosses 0.5: no acne, no leak, but the continuous errors see it.
TEST(Metrics, PartialDarkeningShowsInTheContinuousErrors) {
  const Truth t = hand_truth();
  std::vector<float> v(10, 0.0f);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = t.lit[i] ? 0.875f : 0.25f;
  const Metrics m = compare(t, v);
  EXPECT_EQ(m.acne_rate, 0.0);
  EXPECT_EQ(m.leak_rate, 0.0);
  EXPECT_DOUBLE_EQ(m.lit_error, 0.125);
  EXPECT_DOUBLE_EQ(m.shadow_error, 0.25);
}

TEST(Metrics, EdgeErrorsStayOutOfInteriorRates) {
  Truth t = hand_truth();
  std::vector<float> v = kHandVisibility;
  v[1] = 1.0f;  // fix the interior errors
  v[3] = 0.0f;
  v[4] = 0.0f;
  v[8] = 0.0f;
  const Metrics m = compare(t, v);
  EXPECT_EQ(m.acne_rate, 0.0);
  EXPECT_EQ(m.leak_rate, 0.0);
  EXPECT_EQ(m.bleeding_rate, 0.0);
  EXPECT_EQ(m.mae_interior, 0.0);
  EXPECT_DOUBLE_EQ(m.acne_rate_all, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.leak_rate_all, 1.0 / 5.0);
  EXPECT_DOUBLE_EQ(m.mae_edge, (0.75 + 0.875) / 2.0);
}

TEST(Metrics, BleedingThreshold) {
  Truth t;
  t.width = 4;
  t.height = 1;
  t.valid = {1, 1, 1, 1};
  t.lit = {0, 0, 0, 0};
  t.interior = {1, 1, 1, 1};
  const Metrics m = compare(t, {0.0f, 0.1f, 0.125f, 0.49f});
  EXPECT_DOUBLE_EQ(m.bleeding_rate, 2.0 / 4.0);  // > 0.1 strictly: 0.125 and 0.49
  EXPECT_EQ(m.leak_rate, 0.0);                   // all below 0.5
  EXPECT_EQ(m.acne_rate, 0.0);                   // no lit pixels: denominator 0
}

TEST(Metrics, ZeroDenominatorsAndBadInput) {
  Truth t = hand_truth();
  std::fill(t.valid.begin(), t.valid.end(), 0);
  const Metrics m = compare(t, kHandVisibility);
  EXPECT_EQ(m.valid_pixels, 0u);
  EXPECT_EQ(m.acne_rate, 0.0);
  EXPECT_EQ(m.leak_rate, 0.0);
  EXPECT_EQ(m.acne_rate_all, 0.0);
  EXPECT_EQ(m.leak_rate_all, 0.0);
  EXPECT_EQ(m.mae_interior, 0.0);
  EXPECT_EQ(m.mae_edge, 0.0);
  EXPECT_EQ(m.bleeding_rate, 0.0);
  EXPECT_THROW((void)compare(hand_truth(), std::vector<float>(9, 0.0f)), std::invalid_argument);
  EXPECT_THROW((void)diff_image(hand_truth(), std::vector<float>(11, 0.0f)), std::invalid_argument);
}

// NaN is the wrong answer; out-of-range values decide lit/shadowed as if clamped but count in full in the
// mean errors (1.5 on a lit pixel is 0.5 too bright, -0.5 in a shadow 0.5 too dark).
TEST(Metrics, NanCountsAsWrongAndOutOfRangeValuesAreErrors) {
  Truth t;
  t.width = 4;
  t.height = 1;
  t.valid = {1, 1, 1, 1};
  t.lit = {1, 0, 1, 0};
  t.interior = {1, 1, 1, 1};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Metrics m = compare(t, {nan, nan, 1.5f, -0.5f});
  EXPECT_DOUBLE_EQ(m.acne_rate, 0.5);
  EXPECT_DOUBLE_EQ(m.leak_rate, 0.5);
  EXPECT_DOUBLE_EQ(m.mae_interior, 0.75);  // errors 1, 1, 0.5, 0.5
  EXPECT_DOUBLE_EQ(m.lit_error, 0.75);
  EXPECT_DOUBLE_EQ(m.shadow_error, 0.75);
}

TEST(Metrics, JsonHasEveryField) {
  const Metrics m = compare(hand_truth(), kHandVisibility);
  const nlohmann::json j = to_json(m);
  std::set<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.insert(key);
  EXPECT_EQ(keys, (std::set<std::string>{"acne_rate", "leak_rate", "acne_rate_all", "leak_rate_all", "mae_interior",
                                         "mae_edge", "bleeding_rate", "lit_error", "shadow_error", "valid_pixels", "interior_lit",
                                         "interior_shadowed", "edge_pixels"}));
  EXPECT_EQ(j.at("acne_rate").get<double>(), m.acne_rate);
  EXPECT_EQ(j.at("mae_interior").get<double>(), m.mae_interior);
  EXPECT_EQ(j.at("bleeding_rate").get<double>(), m.bleeding_rate);
  EXPECT_EQ(j.at("valid_pixels").get<std::uint64_t>(), 8u);
  EXPECT_EQ(j.at("interior_shadowed").get<std::uint64_t>(), 4u);
  EXPECT_EQ(j.at("edge_pixels").get<std::uint64_t>(), 2u);
}

TEST(Metrics, DiffImageColoursAndRowFlip) {
  // Truth rows are bottom-first: truth row 0 (pixels 0-4) becomes image row 1, truth row 1 image row 0.
  const std::vector<std::uint8_t> img = diff_image(hand_truth(), kHandVisibility);
  ASSERT_EQ(img.size(), 5u * 2u * 4u);
  auto at = [&](int truth_pixel) {
    const int x = truth_pixel % 5, y = truth_pixel / 5;
    const std::size_t o = (static_cast<std::size_t>(1 - y) * 5 + static_cast<std::size_t>(x)) * 4;
    return std::vector<int>{img[o], img[o + 1], img[o + 2], img[o + 3]};
  };
  EXPECT_EQ(at(0), (std::vector<int>{200, 200, 200, 255}));  // lit, agrees
  EXPECT_EQ(at(1), (std::vector<int>{255, 0, 0, 255}));      // acne
  EXPECT_EQ(at(2), (std::vector<int>{70, 70, 70, 255}));     // shadowed, agrees
  EXPECT_EQ(at(3), (std::vector<int>{0, 160, 255, 255}));    // leak
  EXPECT_EQ(at(4), (std::vector<int>{70, 70, 70, 255}));     // 0.0625: shadowed, agrees
  EXPECT_EQ(at(5), (std::vector<int>{255, 110, 0, 255}));    // edge acne: (255,0,0) halfway to yellow
  EXPECT_EQ(at(6), (std::vector<int>{128, 190, 128, 255}));  // edge leak: (0,160,255) halfway to yellow
  EXPECT_EQ(at(7), (std::vector<int>{0, 0, 0, 255}));        // invalid
  EXPECT_EQ(at(8), (std::vector<int>{70, 70, 70, 255}));     // 0.375: shadowed, agrees
  EXPECT_EQ(at(9), (std::vector<int>{0, 0, 0, 255}));        // invalid (NaN ignored)

  // Agreeing edge pixels: the greys tinted.
  Truth t;
  t.width = 2;
  t.height = 1;
  t.valid = {1, 1};
  t.lit = {1, 0};
  t.interior = {0, 0};
  const std::vector<std::uint8_t> e = diff_image(t, {1.0f, 0.0f});
  EXPECT_EQ(std::vector<int>(e.begin(), e.begin() + 4), (std::vector<int>{228, 210, 100, 255}));
  EXPECT_EQ(std::vector<int>(e.begin() + 4, e.end()), (std::vector<int>{163, 145, 35, 255}));
}

}  // namespace
}  // namespace shadowlab
