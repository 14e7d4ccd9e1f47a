// Figures `shadowlab bench` reports beside its sweep of technique x map size x scene. Each function
// measures and returns data; it prints nothing.
//   - the blur methods side by side: time per pass of the taught separable blur, the fast separable
//     blur and the brute-force 2D blur, and how far each one's moments are from the taught one's;
//   - every shadow technique and light type, pass by pass;
//   - the oracle's cost: BVH build and shadow rays per second for each kind of edge band.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "oracle/oracle.h"
#include "core/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

// The median (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> v);

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

// The median time of each pass of one technique's frame.
struct TechniquePasses {
  std::string name;                       // "pcf 3x3", "point 1 pass (GS)", "volumes z-fail", ...
  std::map<std::string, double> pass_ms;  // pass name -> median ms over the timed frames
  double total_ms = 0.0;                  // the medians' sum
};

// Every technique and light type the renderer has (the depth map with one tap and PCF, a spot, a point
// light's cube in six passes and in one, the moments with and without a blur, shadow volumes z-fail and
// z-pass, and the geometry-shader views): per case, the features are switched on (which makes every
// pass run again), one warm-up frame compiles the shaders, then `frames` frames are timed, each
// forced to redraw its shadow map. Maps are map_size^2, the view width x height. Needs a scene.
std::vector<TechniquePasses> measure_technique_passes(Renderer& renderer, int map_size, int width, int height,
                                                      int frames);

// One oracle evaluation of a G-buffer.
struct OracleRun {
  std::string what;  // the light and edge band
  double ms = 0.0;   // median wall time of `repeats` evaluations after a warm-up
  std::uint64_t rays = 0;
  long edge_pixels = 0;  // valid pixels on an edge (not interior)
  double mrays_per_s() const { return ms > 0.0 ? 1e-3 * static_cast<double>(rays) / ms : 0.0; }
};
struct OracleCost {
  std::size_t triangles = 0;
  double build_ms = 0.0;  // median BVH build of `repeats` oracles of the scene
  std::vector<OracleRun> runs;
};

// The oracle on `gbuffer` (a frame of `scene`): the directional light with the default band of 8
// samples, a 3-pixel screen band and no band; `positional` with the default band.
OracleCost measure_oracle_cost(const Scene& scene, const GBuffer& gbuffer, const OracleLight& directional,
                               const OracleLight& positional, int repeats);

}  // namespace shadowlab
