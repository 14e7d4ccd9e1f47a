// The blur methods side by side (issue 6): GPU time per pass of the taught separable blur, the fast
// separable blur and the brute-force 2D blur, and how far each one's moments are from the taught one's.
// For `shadowlab bench`; prints nothing, returns data.
#pragma once

#include <string>
#include <vector>

#include "renderer/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

struct BlurTiming {
  std::string method;  // "separable", "fast", "brute2d" (the vsm.blur_method choices)
  int radius = 0;
  double sigma = 0.0;
  int map_size = 0;
  std::string format;  // "RG32F" or "RG16F"
  // Medians over the timed frames, GPU ms (timer queries). brute2d has one pass (the 2D blur and its
  // copy back into the moments texture): ms_x holds it and ms_y is 0.
  double ms_x = 0.0, ms_y = 0.0, ms_total = 0.0;
  // max |moments - separable's moments| over all texels and both channels (0 for separable itself);
  // non_finite counts NaN/Inf texels in this method's output.
  double max_abs_diff_vs_separable = 0.0;
  long non_finite = 0;
};

// For each radius (> 0) and each method: one warm-up frame (compiles the programs), then `frames`
// frames in which the three methods take turns (so they are measured under the same conditions), each
// forcing the moments and blur passes to run again (Renderer::invalidate_shadow_map). sigma = radius / 2
// (lab 5's check: the kernel spans +-2 sigma). Map size and moments format are the params' own.
// Needs a renderer with a scene and a lab using the moments technique (else read_moments throws).
// Leaves the renderer's shadow map invalidated.
std::vector<BlurTiming> measure_blur_methods(Renderer& renderer, const ParamSet& params, const std::vector<int>& radii,
                                             int frames);

}  // namespace shadowlab
