// An AO image (1 open, 0 occluded, one value per pixel in the G-buffer's order) against the AO truth
// (oracle/ao_truth.h) on the interior: pixels with no depth discontinuity, nor the background, within
// kAoInteriorMargin pixels, the rule of lab 17's check (labs/17_ssao/lab.cpp), where screen-space AO has
// the depth it needs on every side. The bench's AO front and tests/test_gl_gtao.cpp grade with it.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/ao_truth.h"

namespace shadowlab {

// A pixel is on a depth discontinuity when a 4-neighbour lies off its tangent plane by more than this
// share of the radius; interior pixels have none within kAoInteriorMargin pixels (lab 17's values).
inline constexpr float kAoDiscontinuityShare = 0.1f;
inline constexpr int kAoInteriorMargin = 4;
// The interior's two regions: pixels the truth sees open (>= kAoOpenTruth) and occluded (< kAoOccludedTruth).
inline constexpr double kAoOpenTruth = 0.95;
inline constexpr double kAoOccludedTruth = 0.8;

struct AoInteriorError {
  double mean = 1.0;           // mean |AO - truth| over the interior (1 where there is none)
  double mean_signed = 0.0;    // mean AO - truth
  double open = 1.0;           // mean |AO - truth| where the truth is open
  double occluded = 1.0;       // mean |AO - truth| where the truth is occluded
  long interior_pixels = 0, open_pixels = 0, occluded_pixels = 0;
};

// What lab 17's camera frames (labs/17_ssao/lab.cpp): the meshes' box without the flat ones (thinner than
// 1e-3 in y: the ground, a receiver), so that the radius spans enough pixels; the scene's box when all are flat.
Bounds ao_view_bounds(const Scene& scene);

// 1 on interior pixels (covered, no discontinuity within kAoInteriorMargin pixels).
std::vector<std::uint8_t> ao_interior(const GBuffer& gbuffer, float radius);

// Throws std::invalid_argument when the AO image or the truth does not match the G-buffer's size.
AoInteriorError ao_interior_error(const GBuffer& gbuffer, const std::vector<float>& ao, const AoTruth& truth,
                                  float radius);

}  // namespace shadowlab
