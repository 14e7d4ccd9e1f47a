// Panel widgets generated from parameter declarations: one declaration, one widget.
#pragma once

#include <functional>

#include "core/params.h"

namespace shadowlab {

// Draws a widget for every parameter `shown` accepts, in their declared order; returns the union of the
// invalidation bits of what changed.
unsigned param_widgets(ParamSet& params, const std::function<bool(const ParamSpec&)>& shown);

}  // namespace shadowlab
