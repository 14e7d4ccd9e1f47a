// What a frame did and cost: the passes that ran, with their times, and counters over the renderer's
// lifetime, so tests and benchmarks can see what was skipped.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowlab {

struct PassTiming {
  std::string_view name;    // a string literal: recording a pass allocates nothing
  double gpu_ms = 0.0;      // the pass's cost: its timer query, or its wall time where that is the truth
  bool wall_clock = false;  // gpu_ms is the glFinish-bracketed wall time (see PassTimer)
  double wall_ms = 0.0;     // the glFinish-bracketed wall time around the pass (Exact timing only)
  bool timed = false;       // gpu_ms holds a measurement (false: the pass ran, its time is not known yet)
};

struct FrameStats {
  // This frame's passes, in order; with their times under TimingMode::Exact (see PassTimer).
  std::vector<PassTiming> passes;
  // Under TimingMode::Queries: the passes of the latest frame whose timer queries have come back,
  // timed_frames_ago frames before this one (empty, 0 until one has).
  std::vector<PassTiming> timed_passes;
  long timed_frames_ago = 0;
  // The passes the pass-time line shows: this frame's when timed, else the latest timed frame's.
  const std::vector<PassTiming>& shown_passes() const {
    return !passes.empty() && passes.front().timed ? passes : timed_passes;
  }
  double cpu_ms = 0.0;  // wall time of render() (under Exact timing every pass is finished inside it)
  // Counters over the renderer's lifetime, so tests can see what was skipped.
  long frames = 0;
  long shadow_passes = 0;   // shadow-map updates (depth, cube or moments) of the frame's light (the sun)
  // Updates of the maps of the shadowed lights beside the frame light (Features::lights), all entries
  // together (lab 15: its one entry, the flashlight; each entry counts its own: ShadowedLight::map_updates).
  long flashlight_shadow_passes = 0;
  long moments_passes = 0;  // of which moments passes
  long blur_passes = 0;     // blur passes, one per direction (X and Y: two per blurred shadow map; brute2d: one)
  long cube_faces = 0;      // cube-map faces rendered for point lights (six per shadow pass)
  long stencil_passes = 0;  // shadow-volume stencil passes
  long draws = 0;
  // What timing cost the pipeline (lifetime): glFinish calls and query reads that wait for the GPU.
  long gl_finishes = 0;
  long blocking_query_reads = 0;
  // Shadow casters not drawn into a shadow map (or cube face) because their bounds lie outside the
  // light's volume: they could not have written a texel.
  long casters_culled = 0;
  // Fragments that passed the depth test in the shadow passes (GL_SAMPLES_PASSED; a texel written twice
  // counts twice), plus every texel a blur pass wrote.
  long shadow_texels_written = 0;
  // With RG16F moments: the share of covered texels whose variance came out negative (float16
  // cancellation), measured after each moments update (a read-back, done only for RG16F); -1 otherwise.
  double moments_negative_variance = -1.0;
  nlohmann::json to_json() const;
};

}  // namespace shadowlab
