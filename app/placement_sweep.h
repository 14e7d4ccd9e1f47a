// The same scene at any offset and scale (core/placement.h): every technique and light type is
// rendered with its lab's solution at the origin at scale 1, then moved and scaled, and the error against
// the oracle (acne + leak over all graded pixels, as the stress suite measures it) is compared. The CI
// test (tests/test_gl_stress.cpp) runs a sample of the grid; `shadowlab bench --placement` runs all of it
// and prints the table of README "Limits, measured".
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "grading/check.h"
#include "core/placement.h"

namespace shadowlab {

struct PlacementTechnique {
  std::string name;                      // "depth map, directional (lab 1)"
  std::string lab;                       // whose solution renders it: the lab's slug ("bias_tuning")
  std::vector<std::string> assignments;  // over the lab's defaults (e.g. light.type=point)
};
// Every shadow technique with each light type it serves: depth map (lab 1's slope bias), the fitted
// ortho box (lab 2's C++ fit), PCF, VSM blurred, EVSM, MSM, spot, point (cube), shadow volumes with a
// directional and a point light.
std::vector<PlacementTechnique> placement_techniques();
// The lab whose solution renders the technique (std::invalid_argument when no lab has its slug).
const Lab& placement_lab(const PlacementTechnique& technique);

struct PlacementPoint {
  std::string label;  // "x 1e+06", "scale 1e-04", ...
  Placement placement;
};
// Offsets 1e3 ... 1e7 along +x, +y, +z and the diagonal (-1, 1, -1), scales 1e-4 ... 1e5 by decades, and
// 1e7 on the diagonal at scales 1e-4 and 1e5. `sampled` (for CI, 8 placements): 1e4 and 1e7 along +x, 1e5 +y, 1e6 +z, 1e7 on the diagonal,
// the two extreme scales and one combined point.
std::vector<PlacementPoint> placement_grid(bool sampled);
// The assignments that set a placement (scene.offset_*, scene.scale, scene.local_origin).
std::vector<std::string> placement_assignments(const Placement& placement);

struct PlacementOutcome {
  double error = 0.0;     // acne_rate_all + leak_rate_all
  long non_finite = 0;    // NaN or Inf in the visibility
  double graded = 0.0;    // valid pixels
};
// Renders the technique at this placement on the default scene (framed whole) at width x height and
// measures it against the oracle, through ctx (whose lab must be placement_lab(technique)).
PlacementOutcome measure_placement(CheckContext& ctx, const PlacementTechnique& technique, const Placement& placement,
                                   int width, int height);

// One technique over a grid, against the same scene at the origin at scale 1 (the CI test and the bench).
struct PlacementSweep {
  PlacementOutcome origin;
  std::vector<PlacementOutcome> points;  // one per grid point, in the grid's order
  double worst_offset = 0.0;             // largest |error - origin's| over the points at scale 1
  double worst_scale = 0.0;              // the same over the scaled points
  long non_finite = 0;                   // over the origin and every point
  // The default scene at 1e6 on the diagonal with the local origin off (float world coordinates).
  double error_1e6_without_local_origin = 0.0;
};
// Renders with the technique's lab's solution on the default scene, through a renderer of its own.
PlacementSweep sweep_placements(const PlacementTechnique& technique, const std::vector<PlacementPoint>& grid, int width,
                                int height);

}  // namespace shadowlab
