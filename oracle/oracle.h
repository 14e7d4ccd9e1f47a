// The oracle: exact hard-shadow visibility by ray casting on the CPU (Embree 3 or 4).
//
// Input is what the camera sees (world position and normal per pixel, read back from the renderer's
// G-buffer) and the light; output is, per pixel, whether the point is truly lit, and whether it lies in
// the interior of a lit or shadowed region or in the edge band, where a shadow map cannot be exact.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/scene.h"

namespace shadowlab {

// Every coordinate finite (no NaN, no infinity).
inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What the camera sees, one entry per pixel, row 0 at the bottom (OpenGL's readback order).
struct GBuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::vec3> position;  // world space
  std::vector<glm::vec3> normal;    // world space, unit length (may face away from the camera)
  std::vector<std::uint8_t> covered;  // 1 where geometry was drawn, 0 for background
};

// The G-buffer's pixel count, width x height; throws std::invalid_argument, its message starting with `who`,
// for a negative size or arrays that do not hold one entry per pixel (the hard, soft and AO truths' check).
std::size_t checked_pixel_count(const GBuffer& gbuffer, const char* who);

struct OracleLight {
  bool positional = false;
  glm::vec3 to_light{0, 1, 0};  // directional: unit vector from the scene toward the light
  glm::vec3 position{0};        // positional (spot and point lights)
  // The edge band's radius is measured in shadow-map texels, in the light's image plane. Directional:
  // the world size of one texel and the light's image-plane axes. Positional: the angle one texel spans.
  float texel_world_size = 0.0f;
  glm::vec3 image_x{1, 0, 0};
  glm::vec3 image_y{0, 0, 1};
  float texel_angle = 0.0f;
};

struct BandSpec {
  float radius_texels = 2.0f;  // the definition: a circle of radius 2 shadow-map texels
  int samples = 8;             // points on that circle
  // The benchmark instead uses a band of fixed width in screen pixels (so map sizes compare fairly):
  // when > 0, a pixel is in the band if the truth changes within this many screen pixels of it.
  int fixed_screen_pixels = 0;
  // Pixels lit at a grazing angle, n . l below this, join the band (graded only in the "all" rates):
  // a surface the light barely reaches gets almost none of it, and every shadow-map bias that keeps
  // shadows attached leaves some acne there. 0 grades them all.
  float grazing_n_dot_l = 0.0f;
};

struct Truth {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> valid;        // covered and light-facing (n . l > 0): the pixels metrics use
  std::vector<std::uint8_t> lit;          // truly lit
  std::vector<std::uint8_t> interior;     // truth agrees on the whole band circle (0 = edge band)
  double seconds = 0.0;                   // wall time of the ray casting
  std::uint64_t rays = 0;
};

// Notes on the contract as implemented:
//  - Only meshes with casts_shadow occlude (they are the ones the shadow maps see); all meshes set the
//    ray-offset scale. Throws std::invalid_argument for out-of-range indices, std::runtime_error when
//    Embree fails. The scene's triangles are copied: the Scene need not outlive the Oracle.
//  - evaluate: shadow rays start at p + n * eps, eps = 1e-4 x the scene's bounding-box diagonal + 32 float
//    ulps of max(|p.x|, |p.y|, |p.z|). A band radius of 0 (e.g. texel_world_size or texel_angle left at 0)
//    makes every valid pixel interior with no extra rays. With a positional light, a band circle that
//    reaches past the horizon of the pixel's tangent plane puts the pixel in the edge band. Band sampling
//    stops at the first sample that disagrees, so `rays` counts the rays actually cast. Pixels that are
//    not valid have lit = interior = 0. Throws std::invalid_argument when the G-buffer's arrays do not
//    match its size or the light is degenerate (zero or non-finite direction, non-finite position).
class Oracle {
 public:
  explicit Oracle(const Scene& scene);
  ~Oracle();
  Oracle(const Oracle&) = delete;
  Oracle& operator=(const Oracle&) = delete;

  // True when the segment from origin toward the light (direction, up to max_distance) hits geometry.
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float max_distance) const;

  Truth evaluate(const GBuffer& gbuffer, const OracleLight& light, const BandSpec& band = {}) const;

  // How far a shadow ray from surface point p starts along the normal (see the notes above): the soft
  // truth (oracle/soft_truth.h) starts its rays where this one does.
  float ray_epsilon(const glm::vec3& p) const;

  double build_seconds() const { return build_seconds_; }
  // Triangles in the acceleration structure (meshes with casts_shadow == false are left out).
  std::size_t triangle_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double build_seconds_ = 0.0;
};

}  // namespace shadowlab
