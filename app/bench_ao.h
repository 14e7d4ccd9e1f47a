// The AO front of `shadowlab bench` (issue 39): the AO pass's two methods (renderer/ssao_pass.h) on lab
// 17's scene, camera, radius and a 640 x 360 frame, each point timed (the median GPU ms of the AO passes
// over N frames, after a warm-up) and graded against the exact AO truth (oracle/ao_truth.h, the same
// radius) by the mean |AO - truth| over the interior (oracle/ao_metrics.h, lab 17's rule). SSAO at 8, 16,
// 32 and 64 samples, with and without its blur; GTAO at several slices x steps, blurred (the blur averages
// its 4 x 4 rotations as it does SSAO's). The points are bench.json's kind (scene "AO, default", map_size
// 0), so bench_plots_from_json draws and fronts them as it does the shadows'.
#pragma once

#include <nlohmann/json.hpp>

namespace shadowlab {

class Renderer;

// {"resolution", "radius", "frames_per_point", "truth_seconds", "truth_rays", "error", "points": [{scene,
// technique, family, map_size, gpu_ms, error, pass_ms, open_error, occluded_error, interior_pixels,
// method, samples | directions + steps, blur}]}. `quick`: fewer points and frames.
nlohmann::json measure_ao_front(Renderer& renderer, bool quick);

// The points on the front, fastest first: "front, AO: ssao 8 (0.4 ms, 0.0512) ...".
void print_ao_front(const nlohmann::json& ao);

}  // namespace shadowlab
