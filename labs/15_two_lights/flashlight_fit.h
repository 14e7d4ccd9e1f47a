// Lab 15: the flashlight's view and projection, fitted from the node that carries it (the student's
// exercise.cpp). The solution is core/flashlight.cpp's flashlight_view, which the renderer uses by default.
#pragma once

#include <glm/glm.hpp>

#include "core/light.h"

namespace shadowlab {

LightView flashlight_view_exercise(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds);

// One call of a submitted exercise.cpp, compiled into its own program (grading/cpp_exercise.h): the
// check sends a FlashlightCall, exercise_host.cpp answers with the LightView as a FlashlightAnswer.
struct FlashlightCall {
  float node_to_world[16], box_min[3], box_max[3], cone_deg;
};
struct FlashlightAnswer {
  float view[16], projection[16], image_x[3], image_y[3], world_size[2];
};

}  // namespace shadowlab
