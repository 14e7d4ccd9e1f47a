// main() of a submitted lab 15 exercise when grading compiles it on its own (grading/cpp_exercise.h): each
// FlashlightCall is answered with flashlight_view_exercise's result. Not part of the shadowlab binary.
#include <cstring>

#include "labs/15_two_lights/flashlight_fit.h"
#include "grading/cpp_exercise_host.h"
#include "grading/light_view_answer.h"

int main() {
  using namespace shadowlab;
  return serve_exercise<FlashlightCall, FlashlightAnswer>([](const FlashlightCall& call) {
    glm::mat4 node;
    std::memcpy(&node[0][0], call.node_to_world, sizeof call.node_to_world);
    Bounds box;
    box.min = {call.box_min[0], call.box_min[1], call.box_min[2]};
    box.max = {call.box_max[0], call.box_max[1], call.box_max[2]};
    FlashlightAnswer a;
    put_light_view(flashlight_view_exercise(node, call.cone_deg, box), a);
    return a;
  });
}
