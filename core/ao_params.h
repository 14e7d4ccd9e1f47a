// The AO pass's method (renderer/ssao_pass.h) and GTAO's sampling, declared once in renderer_params.cpp
// beside the ssao.* parameters of lab 17 but not among them (ssao_param_specs() is lab 17's slider list):
// a lab or the bench declares these; an undeclared key reads as the handle's default (ssao).
#pragma once

#include <vector>

#include "core/params.h"

namespace shadowlab {

// ssao.method (ssao | gtao), ssao.gtao_directions, ssao.gtao_steps.
std::vector<ParamSpec> ao_method_param_specs();

namespace param {
extern const ChoiceParam ssao_method;
extern const IntParam ssao_gtao_directions;
extern const IntParam ssao_gtao_steps;
}  // namespace param

}  // namespace shadowlab
