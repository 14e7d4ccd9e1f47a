// main() of a submitted lab 2 exercise when grading compiles it on its own (labs/cpp_exercise.h): each
// FitCall is answered with ortho_fit_exercise's result. Not part of the shadowlab binary.
#include <cstring>

#include "labs/02_ortho_fit/ortho_fit.h"
#include "labs/cpp_exercise_host.h"

int main() {
  using namespace shadowlab;
  return serve_exercise<FitCall, FitAnswer>([](const FitCall& call) {
    Bounds box;
    box.min = {call.box_min[0], call.box_min[1], call.box_min[2]};
    box.max = {call.box_max[0], call.box_max[1], call.box_max[2]};
    const LightView v = ortho_fit_exercise(box, {call.to_light[0], call.to_light[1], call.to_light[2]});
    FitAnswer a;
    std::memcpy(a.view, &v.view[0][0], sizeof a.view);
    std::memcpy(a.projection, &v.projection[0][0], sizeof a.projection);
    for (int i = 0; i < 3; ++i) {
      a.image_x[i] = v.image_x[i];
      a.image_y[i] = v.image_y[i];
    }
    a.world_size[0] = v.world_size.x;
    a.world_size[1] = v.world_size.y;
    return a;
  });
}
