// Panel widgets generated from parameter declarations: one declaration, one widget.
#pragma once

#include "core/params.h"

namespace shadowlab {

// Draws a widget for every parameter; returns the union of the invalidation bits of what changed.
unsigned param_widgets(ParamSet& params);

}  // namespace shadowlab
