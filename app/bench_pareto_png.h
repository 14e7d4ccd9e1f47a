// The speed-against-error plots of `shadowlab bench` as pictures (pareto.png, pareto_light_size.png,
// ao_pareto.png), drawn offscreen by the code that draws them in the window's panel (app/bench_plot.h).
#pragma once

#include <filesystem>

#include "app/bench_plot.h"

namespace shadowlab {

// One tile per scene; `sized_lights`: the tiles of the suns with a size instead (two per row: one scene's
// sizes side by side). False when there is no such tile (a run recorded before light sizes): nothing written.
bool write_pareto_png(const BenchPlots& plots, const std::filesystem::path& file, bool sized_lights = false);

}  // namespace shadowlab
