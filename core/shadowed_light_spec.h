// A shadowed light beside the frame's own light (the sun), as a feature asks for it: one entry of
// Features::lights (renderer/renderer.h). The renderer holds every shadowed light in one list of
// ShadowedLight (renderer/shadowed_light.h): entry 0 the frame's own light, placed from the parameters and
// drawn by the features' technique, then one entry per spec here, each with its own perspective depth map,
// inputs and lit uniforms; a further light is one more spec and no new member anywhere. Today every spec is
// a spot (lab 15's flashlight, core/flashlight.h's flashlight_spec()).
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
