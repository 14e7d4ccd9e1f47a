// Lab 12 exercise: cascaded shadow maps. Write the split distances and each cascade's light box.
// Edit these functions, save, and run: shadowlab check --lab 12 --impl exercise. On Linux Check builds your
// saved file on its own and the window builds it and draws with it; on Windows and macOS rebuild first
// (bash scripts/build).
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "labs/12_cascaded_shadow_maps/cascades_lab.h"

namespace shadowlab {

std::vector<float> cascade_splits_exercise(float near_plane, float far_plane, int count, float lambda) {
  (void)lambda;
  // TODO: the practical split scheme. For i = 0..count, with t = i / count:
  //   logarithmic  C_log = n (f / n)^t        equal far / near ratio per cascade
  //   uniform      C_uni = n + (f - n) t      equal depth per cascade
  //   C_i = lambda C_log + (1 - lambda) C_uni
  // Return count + 1 distances: C_0 = near_plane, ..., C_count = far_plane.
  std::vector<float> splits;
  for (int i = 0; i <= count; ++i) splits.push_back(near_plane + (far_plane - near_plane) * static_cast<float>(i) / count);
  return splits;
}

LightView cascade_fit_exercise(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene) {
  // TODO: the stock box is fitted tightly around the slice's corners in the light's image plane. It
  // covers the slice, but its size changes whenever the camera turns, and it slides by fractions of a
  // texel whenever the camera moves: shadow edges shimmer and crawl. Replace it:
  //   1. The slice's bounding sphere: centre C = the mean of the 8 corners, radius r = the largest
  //      distance from C to a corner. r depends on the slice alone, not on where the camera looks.
  //   2. The light's axes X, Y, Z = the columns of orthonormal_basis(to_light) (Z toward the light).
  //   3. Snap C's coordinates along X and Y (dot products: light space, not world x, y, z) down to whole
  //      texels: floor(x / texel) * texel. The snap moves the box by up to one texel, so make it one
  //      texel wider than the sphere on each side: texel = 2 r / (map_size - 2), half-size h = texel *
  //      map_size / 2.
  //   4. Depth: the scene's box along Z, as lab 2 fits it (around the box's centre, so it is the same
  //      every frame): half-depth hz = the largest |(V - B) . Z| over the box's corners, B its centre.
  //   5. Origin O = X x' + Y y' + Z (B . Z); view = rows X, Y, Z with origin O;
  //      projection = glm::ortho(-h, h, -h, h, -hz, hz); image_x = X, image_y = Y, world_size = (2 h, 2 h).
  const glm::mat3 basis = orthonormal_basis(glm::normalize(to_light));
  const glm::vec3 centre = scene.center();
  glm::vec2 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& corner : slice) {
    const glm::vec2 p(glm::dot(corner - centre, basis[0]), glm::dot(corner - centre, basis[1]));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  float hz = 0.0f;
  for (int i = 0; i < 8; ++i) hz = std::max(hz, std::abs(glm::dot(scene.corner(i) - centre, basis[2])));
  const glm::vec2 mid = 0.5f * (lo + hi), half = 0.5f * (hi - lo);
  const float extent = std::max(half.x, half.y);
  const glm::vec3 origin = centre + basis[0] * mid.x + basis[1] * mid.y;
  const glm::mat3 rows = glm::transpose(basis);
  LightView v;
  v.view = glm::mat4(rows);
  v.view[3] = glm::vec4(-(rows * origin), 1.0f);
  v.projection = glm::ortho(-extent, extent, -extent, extent, -hz, hz);
  v.image_x = basis[0];
  v.image_y = basis[1];
  v.world_size = glm::vec2(2.0f * extent);
  (void)map_size;
  return v;
}

}  // namespace shadowlab
