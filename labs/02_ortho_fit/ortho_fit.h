// Lab 2: the light's ortho projection fitted to the bounding box. The solution is the renderer's own
// fit_light_ortho (core/light.cpp), which every other lab uses.
#pragma once

#include <functional>
#include <vector>

#include "core/light.h"

namespace shadowlab {

LightView ortho_fit_exercise(const Bounds& bounds, const glm::vec3& to_light);

// One call of a submitted exercise.cpp, compiled into its own program (grading/cpp_exercise.h): the
// check sends a FitCall, exercise_host.cpp answers with the fit's LightView as a FitAnswer.
struct FitCall {
  float box_min[3], box_max[3], to_light[3];
};
struct FitAnswer {
  float view[16], projection[16], image_x[3], image_y[3], world_size[2];
};

struct FitVerification {
  int directions = 0;
  int non_finite = 0;     // directions whose matrix has a NaN or Inf
  int outside = 0;        // directions with a corner outside [-1, 1]^3 by more than the tolerance
  int loose = 0;          // directions where the box does not touch both sides of some axis
  double worst_excess = 0.0;  // largest |coordinate| - 1 over all corners (> 0: outside)
  double worst_gap = 0.0;     // largest 1 - max|coordinate| over axes (> 0: not tight)
  // Directions whose image_x, image_y and world_size disagree with the matrix: the axes must be unit,
  // orthogonal to each other and to the light, and a step of world_size along image_x (image_y) must
  // cross the map's width (height) in x (y) alone. The oracle's edge band and the bias's texel size read
  // these fields, so a matrix alone is not the whole answer.
  int inconsistent_axes = 0;
  // Directions where moving toward the light does not decrease the depth (near and far swapped: the
  // map then keeps the farthest surfaces).
  int depth_reversed = 0;
};

// The directions verify_light_fit tries: the six axes, then `random_directions` from a fixed seed.
std::vector<glm::vec3> fit_test_directions(int random_directions = 10000);

// Fits the box for 10,000 random directions plus the six axis directions and checks that every corner
// maps into [-1, 1]^3 within `tolerance` and touches the boundary on each axis.
FitVerification verify_light_fit(const std::function<LightView(const Bounds&, const glm::vec3&)>& fit,
                                 const Bounds& bounds, int random_directions = 10000, double tolerance = 1e-5);

}  // namespace shadowlab
