// The variance-shadow-map parameters (vsm.*), declared once in renderer_params.cpp. They are not in
// renderer_param_specs(): only a feature set that switches the moments technique on declares them (all
// or a subset), so the depth-map panels stay short. The renderer reads them through their handles (below): an
// undeclared vsm.* key reads as the handle's declared default.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/params.h"

namespace shadowlab {

std::vector<ParamSpec> vsm_param_specs();
// The subset with these keys, in declaration order; throws std::out_of_range for an unknown key.
std::vector<ParamSpec> vsm_param_specs(const std::vector<std::string>& keys);

// Their handles.
namespace param {
extern const ChoiceParam vsm_format;
extern const FloatParam vsm_min_variance;
extern const FloatParam vsm_bleed_delta;
extern const BoolParam vsm_show_remap;
extern const IntParam vsm_blur_radius;
extern const FloatParam vsm_blur_sigma;
extern const ChoiceParam vsm_blur_method;
extern const ChoiceParam vsm_warp;
extern const FloatParam vsm_evsm_exponent;
extern const FloatParam vsm_evsm_negative_exponent;
extern const BoolParam vsm_match_light;
extern const DoubleParam vsm_match_distance;
extern const FloatParam vsm_msm_moment_bias;
}  // namespace param

}  // namespace shadowlab
