// A LightView in the reply of a C++ exercise's program (grading/cpp_exercise.h): a lab's answer struct
// carries it as plain floats, `view[16], projection[16], image_x[3], image_y[3], world_size[2]`; the
// lab's host fills them (put_light_view) and its check reads them back (light_view_of). Labs 2 and 12.
#pragma once

#include <cstring>

#include "core/light.h"

namespace shadowlab {

template <typename Answer>
void put_light_view(const LightView& v, Answer& a) {
  std::memcpy(a.view, &v.view[0][0], sizeof a.view);
  std::memcpy(a.projection, &v.projection[0][0], sizeof a.projection);
  for (int i = 0; i < 3; ++i) {
    a.image_x[i] = v.image_x[i];
    a.image_y[i] = v.image_y[i];
  }
  a.world_size[0] = v.world_size.x;
  a.world_size[1] = v.world_size.y;
}

template <typename Answer>
LightView light_view_of(const Answer& a) {
  LightView v;
  std::memcpy(&v.view[0][0], a.view, sizeof a.view);
  std::memcpy(&v.projection[0][0], a.projection, sizeof a.projection);
  v.image_x = {a.image_x[0], a.image_x[1], a.image_x[2]};
  v.image_y = {a.image_y[0], a.image_y[1], a.image_y[2]};
  v.world_size = {a.world_size[0], a.world_size[1]};
  return v;
}

}  // namespace shadowlab
