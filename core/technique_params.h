// Parameters of the light types and of the techniques beyond the plain directional shadow map, declared
// once in renderer_params.cpp. Like the vsm.* keys they are not in renderer_param_specs(): a feature set
// declares the ones it uses (all or a subset, possibly with its own defaults), so the others' parameter
// lists stay short. The renderer reads them through their handles (below): an undeclared key reads as the
// handle's declared default.
//
//   light.*   the light's type (directional, spot, point), a positional light's place and a spot's cone
//   pcf.*     percentage-closer filtering: kernel size, hardware comparison
//   point.*   the cube shadow map of a point light
//   volume.*  stencil shadow volumes
//   ssao.*    screen-space ambient occlusion (renderer/ssao_pass.h), when the features switch it on
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"

namespace shadowlab {

enum class LightType { Directional, Spot, Point };

std::vector<ParamSpec> light_param_specs();
std::vector<ParamSpec> pcf_param_specs();
std::vector<ParamSpec> point_param_specs();
std::vector<ParamSpec> volume_param_specs();
std::vector<ParamSpec> ssao_param_specs();
// The specs with these keys from any of the groups above, in the order given; throws std::out_of_range
// for an unknown key.
std::vector<ParamSpec> technique_param_specs(const std::vector<std::string>& keys);

// Their handles, in the groups' order.
namespace param {
extern const ChoiceParam light_type;
extern const FloatParam light_position_x;
extern const FloatParam light_position_y;
extern const FloatParam light_position_z;
extern const FloatParam light_cone_deg;
extern const ChoiceParam pcf_kernel;
extern const BoolParam pcf_hardware;
extern const BoolParam pcf_match_light;
extern const DoubleParam pcf_match_distance;
extern const IntParam pcss_blocker_samples;
extern const IntParam pcss_filter_samples;
extern const ChoiceParam pcss_view;
extern const FloatParam pcss_view_range;
extern const BoolParam point_single_pass;
extern const ChoiceParam volume_method;
extern const FloatParam ssao_radius;
extern const IntParam ssao_samples;
extern const FloatParam ssao_bias;
extern const BoolParam ssao_range_check;
extern const BoolParam ssao_blur;
extern const BoolParam ssao_noise;
}  // namespace param

LightType light_type(const ParamSet& params);
const char* light_type_name(LightType type);

}  // namespace shadowlab
