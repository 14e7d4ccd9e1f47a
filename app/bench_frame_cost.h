// What a frame of `shadowlab bench` costs beside its sweep: the steady frame with the shadow pass skipped
// and redone, the views (debug quads, light volume, panel) shown and hidden, and the lab's windowed frame
// against the bare two-pass baseline (app/bench_baseline.h) with every lab's frame against its lit pass.
// Each measures and returns JSON; print_* prints it.
#pragma once

#include <nlohmann/json.hpp>

#include "core/scene.h"
#include "grading/lab.h"
#include "renderer/renderer.h"

namespace shadowlab {

// The benchmark's frame: its sweep's, its oracle's and its soft truth's.
inline constexpr int kBenchWidth = 640, kBenchHeight = 360;

// The benchmark's frame: kBenchWidth x kBenchHeight, the camera framing `view`.
FrameRequest bench_request(const Bounds& view);

// The lab the skipping, overlay and blur figures use: the first whose solution stores moments and
// declares a blur (the most a skipped shadow update saves).
const Lab& blurred_moments_lab();

nlohmann::json measure_skipping(Renderer& renderer, const Scene& scene, int frames);
void print_skipping(const nlohmann::json& skipping);
nlohmann::json measure_overlays(Renderer& renderer, const Scene& scene, int frames);
void print_overlays(const nlohmann::json& overlays);
nlohmann::json measure_frame_cost(Renderer& renderer, int frames);
void print_frame_cost(const nlohmann::json& frame_cost);

}  // namespace shadowlab
