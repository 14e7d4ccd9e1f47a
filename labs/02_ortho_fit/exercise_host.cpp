// main() of a submitted lab 2 exercise when grading compiles it on its own (grading/cpp_exercise.h): each
// FitCall is answered with ortho_fit_exercise's result. Not part of the shadowlab binary.
#include "labs/02_ortho_fit/ortho_fit.h"
#include "grading/cpp_exercise_host.h"
#include "grading/light_view_answer.h"

int main() {
  using namespace shadowlab;
  return serve_exercise<FitCall, FitAnswer>([](const FitCall& call) {
    Bounds box;
    box.min = {call.box_min[0], call.box_min[1], call.box_min[2]};
    box.max = {call.box_max[0], call.box_max[1], call.box_max[2]};
    const LightView v = ortho_fit_exercise(box, {call.to_light[0], call.to_light[1], call.to_light[2]});
    FitAnswer a;
    put_light_view(v, a);
    return a;
  });
}
