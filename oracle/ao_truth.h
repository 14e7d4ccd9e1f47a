// The ambient-occlusion truth: per pixel, the cosine-weighted share of the hemisphere around the normal
// from which no surface lies within `radius` (the "shadows of indirect light": a sky of uniform radiance,
// every surface an occluder, occlusion counted only nearby). 1 is open, 0 fully enclosed. This is the
// quantity screen-space AO approximates (Crytek's SSAO, HBAO, GTAO), with the same radius.
//
// Estimated with strata x strata rays per pixel: a grid of equal-area cells over the unit disk
// (Shirley and Chiu's concentric map, jittered per pixel as the soft truth does) lifted to the
// hemisphere (Malley's method: a uniform point of the disk straight up is a cosine-distributed
// direction), so every ray has the same weight and the estimate is the share of rays that travel
// `radius` freely. Rays start where the hard truth's do (Oracle::ray_epsilon).
//
// Every mesh occludes: build the oracle from ao_occluders(scene) (a mesh that casts no shadow still
// hides the sky). Its sampling error against closed forms (a plane beside a wall, a corner) is measured
// by tests/test_ao_truth.cpp and stated in kAoTruthError.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/oracle.h"

namespace shadowlab {

struct AoTruth {
  int width = 0;
  int height = 0;
  int samples = 0;                  // rays per valid pixel (strata^2)
  std::vector<std::uint8_t> valid;  // covered, with a finite position and normal
  std::vector<float> open;          // the unoccluded cosine-weighted share, in [0, 1] (0 where not valid)
  double seconds = 0.0;
  std::uint64_t rays = 0;
};

// The default grid: 16 x 16 = 256 rays per pixel.
inline constexpr int kAoStrata = 16;
// The largest error of the 16 x 16 estimate against the closed forms of tests/test_ao_truth.cpp, rounded
// up: measured 0.0174 beside a wall (64 distances, mean 0.0044) and 0.0201 in a corner (32 distances, mean
// 0.0066). A check that grades an AO image against this truth must allow at least this much per pixel.
inline constexpr double kAoTruthError = 0.025;

// The scene with every mesh an occluder (casts_shadow set), for the oracle the AO truth casts into.
Scene ao_occluders(const Scene& scene);

// Throws std::invalid_argument for a radius that is not finite and positive, strata < 1, or G-buffer
// arrays that do not match its size.
AoTruth evaluate_ao(const Oracle& oracle, const GBuffer& gbuffer, float radius, int strata = kAoStrata);

}  // namespace shadowlab
