#include "core/flashlight.h"

#include <algorithm>
#include <cmath>

#include "core/light.h"

namespace shadowlab {

namespace param {

const FloatParam sun_intensity{{"sun.intensity", "Sun intensity", ParamKind::Float, 1.0, 0.0, 1.5,
    "The sun's Lambert term is multiplied by this before the lights are combined (0: the flashlight alone).", {}}};
const FloatParam flashlight_intensity{{"flashlight.intensity", "Flashlight intensity", ParamKind::Float, 0.8, 0.0, 1.5,
    "The flashlight's Lambert term is multiplied by this before the lights are combined (0: the sun alone).", {}}};
const ChoiceParam flashlight_mount{{"flashlight.mount", "Flashlight carried by", ParamKind::Choice, 0.0, 0.0, 1.0,
    "Node: a node circling the scene carries it, aimed at the scene's centre. Camera: it shines from the "
    "eye along the view.", {"node", "camera"}}};
const DoubleParam flashlight_phase{{"flashlight.phase", "Flashlight node angle (deg)", ParamKind::Float, 200.0, 0.0,
    360.0, "Where the node carrying the flashlight stands on its circle around the scene.", {}}};
const BoolParam flashlight_animate{{"flashlight.animate", "Move the flashlight", ParamKind::Bool, 0.0, 0.0, 1.0,
    "In the window, the node circles the scene at flashlight.speed.", {}}};
const DoubleParam flashlight_speed{{"flashlight.speed", "Flashlight speed (deg/s)", ParamKind::Float, 30.0, -180.0,
    180.0, "How fast the node circles when it moves.", {}}};
const FloatParam flashlight_radius{{"flashlight.radius", "Flashlight circle radius", ParamKind::Float, 0.9, 0.0, 2.0,
    "The node's circle, in half diagonals of the scene's box (0: straight above the centre, pointing straight down).", {}}};
const FloatParam flashlight_height{{"flashlight.height", "Flashlight height", ParamKind::Float, 0.5, 0.05, 2.0,
    "The node's height above the scene's centre, in half diagonals of the scene's box.", {}}};
const FloatParam flashlight_slope_bias{{"flashlight.slope_bias", "Flashlight slope bias", ParamKind::Float, 2.0, 0.0,
    10.0, "The flashlight's slope-scaled bias, in texels per unit of tan(angle of incidence) (lab 7's test and "
    "default): its light meets the ground at a grazing angle far from it.", {}}};
const FloatParam flashlight_cone_deg{{"flashlight.cone_deg", "Flashlight cone half-angle (deg)", ParamKind::Float,
    28.0, 5.0, 60.0, "Half the flashlight's opening angle.", {}}};

}  // namespace param

std::vector<ParamSpec> flashlight_param_specs() {
  return specs_of(param::sun_intensity, param::flashlight_intensity, param::flashlight_mount, param::flashlight_phase,
      param::flashlight_animate, param::flashlight_speed, param::flashlight_radius, param::flashlight_height,
      param::flashlight_slope_bias, param::flashlight_cone_deg);
}

FlashlightMount flashlight_mount(const ParamSet& params) {
  return params.get(param::flashlight_mount) == "camera" ? FlashlightMount::Camera : FlashlightMount::Node;
}

glm::mat4 flashlight_node_to_world(const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view) {
  const glm::vec3 centre = bounds.empty() ? glm::vec3(0.0f) : bounds.center();
  const float half_diagonal = bounds.empty() ? 1.0f : std::max(0.5f * glm::length(bounds.extent()), 1e-6f);
  if (flashlight_mount(params) == FlashlightMount::Camera) {
    // Held a little right of and below the eye: a light exactly at the eye hides every shadow it casts
    // behind the caster that casts it. Its axes are the camera's (it looks where the camera looks).
    const glm::mat4 to_world = glm::inverse(camera_view);
    const glm::vec3 right = glm::normalize(glm::vec3(to_world[0])), up = glm::normalize(glm::vec3(to_world[1]));
    const glm::vec3 back = glm::normalize(glm::vec3(to_world[2]));
    const glm::vec3 position = glm::vec3(to_world[3]) + 0.1f * half_diagonal * (right - up);
    return {glm::vec4(right, 0.0f), glm::vec4(up, 0.0f), glm::vec4(back, 0.0f), glm::vec4(position, 1.0f)};
  }
  const float phase = glm::radians(static_cast<float>(params.get(param::flashlight_phase)));
  const float radius = params.get(param::flashlight_radius) * half_diagonal;
  const float height = params.get(param::flashlight_height) * half_diagonal;
  const glm::vec3 position = centre + glm::vec3(radius * std::cos(phase), height, radius * std::sin(phase));
  const glm::mat3 axes = orthonormal_basis(-glm::normalize(centre - position));  // its -Z toward the centre
  return {glm::vec4(axes[0], 0.0f), glm::vec4(axes[1], 0.0f), glm::vec4(axes[2], 0.0f), glm::vec4(position, 1.0f)};
}

LightView flashlight_view(const glm::mat4& node_to_world, float cone_deg, const Bounds& bounds) {
  return fit_spot_light(bounds, glm::vec3(node_to_world[3]), -glm::normalize(glm::vec3(node_to_world[2])), cone_deg);
}

FrameLight flashlight_light(const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view,
                            const FlashlightFit& fit) {
  FrameLight light;
  light.type = LightType::Spot;
  light.spot_cone_deg = params.get(param::flashlight_cone_deg);
  const glm::mat4 node = flashlight_node_to_world(params, bounds, camera_view);
  light.position = glm::vec3(node[3]);
  light.spot_direction = -glm::normalize(glm::vec3(node[2]));
  light.scene_position = light.position;
  light.to_light = -light.spot_direction;
  light.view = fit(node, light.spot_cone_deg, bounds);
  return light;
}

ShadowedLightSpec flashlight_spec(FlashlightFit fit) {
  return {"flashlight", "flashlight shadow",
          [fit = std::move(fit)](const ParamSet& params, const Bounds& bounds, const glm::mat4& camera_view) {
            return flashlight_light(params, bounds, camera_view, fit);
          },
          [](const ParamSet& params) { return params.get(param::flashlight_intensity); },
          [](const ParamSet& params) { return params.get(param::flashlight_slope_bias); }};
}

double advance_flashlight_phase(const ParamSet& params, double seconds) {
  const double phase = params.get(param::flashlight_phase) + params.get(param::flashlight_speed) * seconds;
  return phase - 360.0 * std::floor(phase / 360.0);
}

}  // namespace shadowlab
