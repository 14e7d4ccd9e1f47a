// Variance shadow maps as a feature set the labs share: lab 4 teaches the VSM test with it, lab 14 measures
// MSM against it, and the VSM labs (4, 5, 13, 14) set the depth bias its way. A lab that needs VSM asks these
// factories, never another lab: a lab's number is its place in the course, not a handle on its code.
#pragma once

#include <filesystem>
#include <vector>

#include "core/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

// The renderer's own VSM test (lab 4's solution): Chebyshev's bound on the biased depth, the bound remapped
// from [vsm.bleed_delta, 1] to [0, 1].
inline constexpr const char* kVsmVisibility = "shaders/vsm/visibility.glsl";

// Two moments per texel (blurred by vsm.blur_*), read by `visibility`: the file behind "lab/visibility.glsl".
Features vsm_features(const std::filesystem::path& visibility = kVsmVisibility);

// shadow.bias and shadow.slope_bias as the VSM labs set them: a bias of 0.0005 on z, no slope term (the
// moments' bias is the lesson there, not the slope).
std::vector<ParamSpec> vsm_lab_bias_params();

// Where the VSM labs' light-bleeding presets look from (PresetView: the built-in "stacked" scene, the
// occluders stacked over the receiver, and this --camera): close over the receiver where the low
// occluder's shadow lies inside the middle one's, so that the band where light bleeds fills the view.
inline constexpr const char* kStackedOccludersScene = "stacked";
inline constexpr const char* kStackedOccludersCamera = "eye=-2,2.6,4.2 target=-0.4,0,1 fov=30";
// Closer still, for EVSM's and MSM's presets (labs 13, 14), whose bleeding is a narrower band than VSM's:
// low beside the low occluder's -x side, looking at the receiver where its shadow edge lies inside the
// middle one's (x -2.5 to -1.2, z -1.2 to 0). From kStackedOccludersCamera, "small c" against "EVSM"
// changes 0.68 % of a 1280x720 frame and "large bias" against "paper" 1.15 %; from here more than 2 %
// (tests/cli.sh preset_contrast prints the figures).
inline constexpr const char* kStackedBleedingCamera = "eye=-3.2,1.7,0.9 target=-1.8,0,-0.6 fov=30";

}  // namespace shadowlab
