// What the panel says about a frame's figures, in words.
#pragma once

#include <string>

#include "renderer/frame_stats.h"

namespace shadowlab {

// Empty when precision held; from 1 % of the moments' texels with a negative variance (float16
// cancellation) a warning, from 50 % a statement that the shadows on screen are wrong.
std::string precision_warning(const FrameStats& stats);

}  // namespace shadowlab
