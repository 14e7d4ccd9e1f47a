// The soft ground truth: the fraction of a light with a size that each pixel sees, by ray casting.
//
// A light with a size is a disk. A directional light (the sun) is a disk at infinity of angular
// diameter `size` (radians), perpendicular to its direction; a positional light is a disk of radius
// `size` (world units) centred on its position and facing the point being shaded. The visible fraction
// of a pixel is the share of the disk's area from which a straight segment reaches the pixel's point:
// 1 lit, 0 umbra, in between penumbra. It is estimated with `strata` x `strata` samples, one per cell
// of a grid over the unit square mapped onto the disk by Shirley and Chiu's concentric map (cells of
// equal area), jittered within their cell by a hash of the pixel (deterministic: the same inputs give
// the same truth). Size 0 is today's hard light: every sample is the centre, and the fraction is 0 or
// 1, equal to Oracle::evaluate's `lit` (tested).
//
// Most pixels of a frame see all of the light or none of it, and 256 rays there only confirm a 1 or a 0.
// EdgeRefined sampling first casts 17 pilot rays per pixel (the centre, 8 points on the disk's rim and 8
// on its half-radius circle between them). A pixel is sampled in full when its pilots disagree, or when
// a neighbour's pilots (valid pixels up to 2 away) disagree or agree on the other answer: so the whole
// penumbra and a ring of pixels around it get the full estimate, bit for bit the one Full sampling gives,
// and the rest keeps the pilots' common answer. What that can miss is a blocker so small that no pilot
// of any pixel around it sees it; its cost and its distance from Full sampling are measured by
// `shadowlab bench` on every benchmark scene (soft_truth_cost) and by tests/test_soft_truth.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "oracle/oracle.h"

namespace shadowlab {

struct SoftTruth {
  int width = 0;
  int height = 0;
  int samples = 0;                      // rays of a pixel sampled in full (strata^2; 1 for a light of size 0)
  std::size_t refined = 0;              // valid pixels sampled in full (all of them with Full sampling)
  std::vector<std::uint8_t> valid;      // as Truth::valid: covered and facing the light's centre
  std::vector<float> visible;           // the visible fraction of the light, in [0, 1] (0 where not valid)
  double seconds = 0.0;
  std::uint64_t rays = 0;
};

// A point on the unit disk for (u, v) in [0, 1)^2: Shirley and Chiu's concentric map, which keeps
// areas (a uniform (u, v) gives a uniform point) and keeps strata compact.
glm::vec2 concentric_disk(float u, float v);

enum class SoftSampling {
  Full,         // strata^2 rays at every valid pixel
  EdgeRefined,  // 17 pilot rays everywhere, strata^2 only in and around the penumbra (see above)
};

// Throws std::invalid_argument for a negative or non-finite size, strata < 1, or what Oracle::evaluate
// refuses (G-buffer arrays that do not match, a degenerate light).
SoftTruth evaluate_soft(const Oracle& oracle, const GBuffer& gbuffer, const OracleLight& light, float size,
                        int strata, SoftSampling sampling = SoftSampling::EdgeRefined);

}  // namespace shadowlab
