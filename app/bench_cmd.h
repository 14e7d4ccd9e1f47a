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
};

int run_bench(const BenchOptions& options);

}  // namespace shadowlab
