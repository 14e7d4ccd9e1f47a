// `shadowlab bench`: run time against error. Sweeps technique x shadow-map size x scene, times every pass
// (warm-up first, median of N frames, timer queries), grades each point against the oracle over all
// pixels with an edge band of fixed width in screen pixels, and writes bench.csv, bench.json and
// pareto.png (drawn by the same ImGui code the app's panel uses).
#pragma once

#include <string>

namespace shadowlab {

struct BenchOptions {
  bool quick = false;
  std::string scene_file;  // replaces the large real model
  std::string out_dir;
  // Only the frame-cost figures (every lab's frame against its lit pass, lab 6 against the bare
  // two-pass baseline): frame_cost.json, in about half a minute.
  bool frame_cost_only = false;
  // Only the soft truth's cost (oracle/soft_truth.h) on every scene: soft_truth.json.
  bool soft_truth_only = false;
  // Only the placement figures (app/bench_placement.h): every technique over offsets and scales, and the
  // frame cost with the local origin against without it; placement.json. --quick: the CI test's sample.
  bool placement_only = false;
  // Only the AO front (app/bench_ao.h): ao_front.json and ao_pareto.png. A whole run measures it too
  // (bench.json's "ao", ao_pareto.png).
  bool ao_only = false;
  // Only pareto.png, drawn again from this bench.json (a recorded run): nothing is measured.
  std::string replot;
};

int run_bench(const BenchOptions& options);

}  // namespace shadowlab
