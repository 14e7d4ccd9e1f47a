// The variance-shadow-map parameters (vsm.*), declared once in renderer_params.cpp. They are not in
// renderer_param_specs(): only a feature set that switches the moments technique on declares them (all
// or a subset), so the depth-map panels stay short. The renderer reads an undeclared vsm.* key as its
// declared default (vsm_param()).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"

namespace shadowlab {

std::vector<ParamSpec> vsm_param_specs();
// The subset with these keys, in declaration order; throws std::out_of_range for an unknown key.
std::vector<ParamSpec> vsm_param_specs(const std::vector<std::string>& keys);
// The value of a vsm.* key when the set declares it, else the declared default.
double vsm_param(const ParamSet& params, std::string_view key);
// The same for a choice, by name.
const std::string& vsm_choice(const ParamSet& params, std::string_view key);

}  // namespace shadowlab
