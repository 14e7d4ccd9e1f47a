// Parameters of the light types and of the techniques beyond the plain directional shadow map, declared
// once in renderer_params.cpp. Like the vsm.* keys they are not in renderer_param_specs(): a feature set
// declares the ones it uses (all or a subset, possibly with its own defaults), so the others' parameter
// lists stay short. The renderer reads an undeclared key as its declared default (technique_param()).
//
//   light.*   the light's type (directional, spot, point), a positional light's place and a spot's cone
//   pcf.*     percentage-closer filtering: kernel size, hardware comparison
//   point.*   the cube shadow map of a point light
//   volume.*  stencil shadow volumes
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
// The specs with these keys from any of the groups above, in the order given; throws std::out_of_range
// for an unknown key.
std::vector<ParamSpec> technique_param_specs(const std::vector<std::string>& keys);
// The value when the set declares the key, else the declared default.
double technique_param(const ParamSet& params, std::string_view key);
const std::string& technique_choice(const ParamSet& params, std::string_view key);

LightType light_type(const ParamSet& params);
const char* light_type_name(LightType type);

}  // namespace shadowlab
