// `shadowlab bench --placement`: the whole offset x scale grid of app/placement_sweep.h for every
// technique (a table: each technique's error at the origin and its worst difference over offsets and over
// scales, and without the local origin at 1e6), and the frame cost with the local origin against
// without it, side by side in one run. Writes placement.json.
#pragma once

#include "app/bench_cmd.h"

namespace shadowlab {

int run_placement_bench(const BenchOptions& options);

}  // namespace shadowlab
