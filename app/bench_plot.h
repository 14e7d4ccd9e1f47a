// The benchmark's results as plots: one error-against-time plot per scene with its Pareto front. Built
// from bench.json's points by one function, so `shadowlab bench` (pareto.png) and the app's panel
// (Speed against error) show the same front from the same data, drawn by the same draw_error_time_plot.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "app/plot.h"

namespace shadowlab {

struct BenchPlots {
  std::vector<std::string> families;                        // colour groups, in order of first appearance
  std::map<std::string, std::vector<PlotPoint>> by_scene;   // each scene's points, in bench.json's order
};

// From bench.json's "points" (scene, technique, family, map_size, gpu_ms, error); marks each scene's
// front. A point's "light_sizes" (sun_deg, error: the frame graded against the truth of a sun with that
// angular diameter; gpu_ms when the technique was timed again at that size) go to plots of their own,
// named by sized_light_plot, each with its front.
// Throws std::runtime_error naming the point and the field when one is missing or not a number.
BenchPlots bench_plots_from_json(const nlohmann::json& report);

// "default, sun 5 deg": the plot of a scene's points graded against a sun of that size.
std::string sized_light_plot(const std::string& scene, double sun_deg);
bool is_sized_light_plot(const std::string& name);

// Reads a bench.json; throws one line naming the file and the problem (missing, not JSON, no points).
BenchPlots load_bench_plots(const std::filesystem::path& file);

// A scene's plot, sized to the space given (the panel's width, or one tile of pareto.png).
void draw_bench_scene(const BenchPlots& plots, const std::string& scene, float width, float height);

// The app's "Speed against error" window (opened from the panel, or by --bench): the file's path, Load,
// a scene picker and the plot, sized to the window; a file that could not be read is named in red.
struct BenchPanelState {
  bool open = false;   // the window is shown
  std::string path;    // the bench.json shown or to load
  std::string scene;   // the scene shown (empty: the first)
  std::string error;   // why the last load failed
};
// Returns true when the user asked to load `state.path`. `interactive` false: no input field or button
// (documentation pictures).
bool draw_bench_window(const BenchPlots* plots, BenchPanelState& state, bool interactive);

}  // namespace shadowlab
