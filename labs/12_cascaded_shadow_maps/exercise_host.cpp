// main() of a submitted lab 12 exercise when grading compiles it on its own (grading/cpp_exercise.h): each
// CascadeCall is answered with the student's splits or cascade box. Not part of the shadowlab binary.
#include <algorithm>

#include "labs/12_cascaded_shadow_maps/cascades_lab.h"
#include "grading/cpp_exercise_host.h"
#include "grading/light_view_answer.h"

int main() {
  using namespace shadowlab;
  return serve_exercise<CascadeCall, CascadeAnswer>([](const CascadeCall& call) {
    CascadeAnswer a{};
    if (call.kind == 0) {
      const std::vector<float> splits = cascade_splits_exercise(call.near_plane, call.far_plane, call.count, call.lambda);
      a.split_count = static_cast<int>(splits.size());
      std::copy_n(splits.begin(), std::min<std::size_t>(splits.size(), kMaxCascades + 1), a.splits);
      return a;
    }
    FrustumCorners slice;
    for (int i = 0; i < 8; ++i) slice[static_cast<std::size_t>(i)] = {call.corners[3 * i], call.corners[3 * i + 1], call.corners[3 * i + 2]};
    Bounds box;
    box.min = {call.box_min[0], call.box_min[1], call.box_min[2]};
    box.max = {call.box_max[0], call.box_max[1], call.box_max[2]};
    const LightView v = cascade_fit_exercise(slice, {call.to_light[0], call.to_light[1], call.to_light[2]}, call.map_size, box);
    put_light_view(v, a);
    return a;
  });
}
