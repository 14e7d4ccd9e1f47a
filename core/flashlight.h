// A second shadowed light beside the frame's own (the sun): a spot, the "flashlight", carried by a node
// that circles the scene (a ship's reflector) or by the camera. It has a shadow map of its own (a
// perspective depth map, DepthMapPass) drawn only when the flashlight, its casters or the map's settings
// change, so that moving it never redraws the sun's map (FrameStats::flashlight_shadow_passes counts its
// updates, shadow_passes the sun's). It is one entry of Features::lights (flashlight_spec()): the lit pass
// gets the SHADOWED_LIGHTS define, and each light's Lambert term and its own shadow term go to
// "lab/combine.glsl" (default shaders/shadow/combine_lights.glsl), which returns the direct light.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/frame_light.h"
#include "core/params.h"
#include "core/shadowed_light_spec.h"

namespace shadowlab {

enum class FlashlightMount { Node, Camera };

// The flashlight.* parameters (and sun.intensity, the sun's weight beside it). None of them invalidates
// the sun's map: the flashlight's map has inputs of its own (see Renderer).
std::vector<ParamSpec> flashlight_param_specs();
namespace param {
extern const FloatParam sun_intensity;
extern const FloatParam flashlight_intensity;
extern const ChoiceParam flashlight_mount;
extern const DoubleParam flashlight_phase;
extern const BoolParam flashlight_animate;
extern const DoubleParam flashlight_speed;
extern const FloatParam flashlight_radius;
extern const FloatParam flashlight_height;
extern const FloatParam flashlight_slope_bias;
extern const FloatParam flashlight_cone_deg;
}  // namespace param

// The world transform of the node that carries the flashlight, in the local frame: rigid (a rotation and
// a translation); the flashlight sits at its origin and shines along its -Z axis (glTF's convention for
// a spot light, KHR_lights_punctual). Either the node circling the scene (flashlight.phase degrees around
// the scene's centre, flashlight.radius and flashlight.height times the scene's half diagonal out and up,
// its -Z aimed at the scene's centre, its X and Y from orthonormal_basis: radius 0 puts it straight above
// the centre, pointing straight down) or the camera's eye, its axes the camera's (flashlight.mount).
// `camera_view` is the view matrix in the same frame as `bounds`.
glm::mat4 flashlight_node_to_world(const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view);

// The flashlight's shadow map's view and projection from its node's transform, its cone's half-angle and
// the scene's box: lab 15's exercise. flashlight_view is the solution (and the renderer's default):
// fit_spot_light at the node's origin along its -Z.
using FlashlightFit = std::function<LightView(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds)>;
LightView flashlight_view(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds);

// The flashlight of a frame, in the local frame: at flashlight_node_to_world's origin along its -Z, its
// map's matrices from `fit`.
FrameLight flashlight_light(const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view,
                            const FlashlightFit& fit = flashlight_view);
FlashlightMount flashlight_mount(const ParamSet& params);
// The flashlight as an entry of Features::lights: named "flashlight", placed by flashlight_light with
// `fit`, weighted by flashlight.intensity (default 0.8), its bias flashlight.slope_bias (default 2).
ShadowedLightSpec flashlight_spec(FlashlightFit fit = flashlight_view);

// The window's animation: the phase after `seconds` more at flashlight.speed degrees per second.
double advance_flashlight_phase(const ParamSet& params, double seconds);

}  // namespace shadowlab
