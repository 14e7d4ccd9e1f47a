// Lab 12: cascaded shadow maps. The student writes the split distances and each cascade's light box
// (its bounding sphere and the texel snapping); the solution is the renderer's own
// (core/cascades.cpp), which the cascade pass uses everywhere else.
#pragma once

#include <vector>

#include "core/cascades.h"
#include "core/light.h"
#include "core/scene.h"

namespace shadowlab {

// count + 1 view depths: near_plane, the count - 1 splits, far_plane.
std::vector<float> cascade_splits_exercise(float near_plane, float far_plane, int count, float lambda);
// The light's view and ortho projection for one cascade.
LightView cascade_fit_exercise(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene);

// One call of a submitted exercise.cpp, compiled into its own program (grading/cpp_exercise.h): kind 0 asks
// for the splits, kind 1 for a cascade's box; exercise_host.cpp answers with a CascadeAnswer.
struct CascadeCall {
  int kind, count, map_size;
  float near_plane, far_plane, lambda;
  float corners[24], to_light[3], box_min[3], box_max[3];
};
struct CascadeAnswer {
  int split_count;  // how many distances the function returned (at most kMaxCascades + 1 are sent)
  float splits[kMaxCascades + 1];
  float view[16], projection[16], image_x[3], image_y[3], world_size[2];
};

}  // namespace shadowlab
