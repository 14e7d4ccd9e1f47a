// A shadowed light beside the frame's own light (the sun), as a feature asks for it: one entry of
// Features::lights (renderer/renderer.h). The renderer gives each entry a ShadowedLight of its own
// (renderer/shadowed_light.h: a perspective depth map, its inputs, its lit uniforms), so a further light is
// one more entry here and no new member anywhere. Today every entry is a spot (lab 15's flashlight,
// core/flashlight.h's flashlight_spec()); the frame's own light stays the primary light outside the list.
#pragma once

#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "core/frame_light.h"
#include "core/params.h"

namespace shadowlab {

struct ShadowedLightSpec {
  std::string name;                 // said on its debug quad ("flashlight: depth")
  const char* pass_name = nullptr;  // its map's pass in the frame's timings: a string literal
  // Where it stands this frame: a spot (type, position, spot_direction, spot_cone_deg, view) in the local
  // frame, from the parameters, the scene's box and the camera's view matrix in that frame.
  std::function<FrameLight(const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view)> place;
  // Its Lambert term's weight, and its slope-scaled bias (texels per unit of tan(angle of incidence)).
  std::function<float(const ParamSet& params)> intensity, slope_bias;
};

}  // namespace shadowlab
