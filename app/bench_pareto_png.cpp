#include "app/bench_pareto_png.h"

#include <string>
#include <vector>

#include <imgui.h>

#include "app/imgui_offscreen.h"
#include "core/image_io.h"

namespace shadowlab {

// The plot: one tile per scene, drawn by the code that draws it in the app's panel; `sized_lights`: the
// tiles of the suns with a size instead (two per row: one scene's sizes side by side). False when there
// is no such tile (a run recorded before light sizes): nothing written.
bool write_pareto_png(const BenchPlots& plots, const std::filesystem::path& file, bool sized_lights) {
  std::vector<std::string> names;
  for (const auto& [name, plot] : plots.by_scene)
    if (is_sized_light_plot(name) == sized_lights) names.push_back(name);
  if (names.empty()) return false;
  const int plot_w = 640, plot_h = 420;
  // Two tiles a row; one tile alone (ao_pareto.png) gets no empty half beside it.
  const int cols = names.size() > 1 ? 2 : 1, rows = static_cast<int>((names.size() + 1) / 2);
  ImGuiOffscreen imgui(cols * plot_w, rows * plot_h);
  const auto pixels = imgui.render([&] {
    int i = 0;
    for (const auto& name : names) {
      ImGui::SetNextWindowPos(ImVec2(static_cast<float>((i % cols) * plot_w), static_cast<float>((i / cols) * plot_h)));
      ImGui::SetNextWindowSize(ImVec2(static_cast<float>(plot_w), static_cast<float>(plot_h)));
      ImGui::Begin(("##plot" + name).c_str(), nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
      draw_bench_scene(plots, name, plot_w - 16.0f, plot_h - 40.0f);
      ImGui::End();
      ++i;
    }
  });
  write_png(file, cols * plot_w, rows * plot_h, pixels);
  return true;
}

}  // namespace shadowlab
