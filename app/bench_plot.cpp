#include "app/bench_plot.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <imgui.h>
#include <imgui_stdlib.h>
#include <nlohmann/json.hpp>

#include "core/platform.h"
#include "core/untrusted.h"

namespace shadowlab {

namespace {

const nlohmann::json& field(const nlohmann::json& point, std::size_t i, const char* name) {
  if (!point.contains(name)) throw std::runtime_error("point " + std::to_string(i) + " has no \"" + name + "\"");
  return point.at(name);
}

double number(const nlohmann::json& point, std::size_t i, const char* name) {
  const auto& v = field(point, i, name);
  if (!v.is_number()) throw std::runtime_error("point " + std::to_string(i) + ": \"" + name + "\" is not a number");
  return v.get<double>();
}

std::string text(const nlohmann::json& point, std::size_t i, const char* name) {
  const auto& v = field(point, i, name);
  if (!v.is_string()) throw std::runtime_error("point " + std::to_string(i) + ": \"" + name + "\" is not a string");
  return v.get<std::string>();
}

}  // namespace

std::string sized_light_plot(const std::string& scene, double sun_deg) {
  char degrees[32];
  std::snprintf(degrees, sizeof degrees, "%g", sun_deg);
  return scene + ", sun " + degrees + " deg";
}

bool is_sized_light_plot(const std::string& name) { return name.find(", sun ") != std::string::npos; }

BenchPlots bench_plots_from_json(const nlohmann::json& report) {
  if (!report.is_object() || !report.contains("points") || !report.at("points").is_array())
    throw std::runtime_error("no \"points\" array (is this a shadowlab bench.json?)");
  BenchPlots plots;
  const auto& points = report.at("points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const std::string family = text(p, i, "family"), technique = text(p, i, "technique"), scene = text(p, i, "scene");
    const int map_size = static_cast<int>(number(p, i, "map_size"));
    auto group = std::find(plots.families.begin(), plots.families.end(), family);
    if (group == plots.families.end()) group = plots.families.insert(plots.families.end(), family);
    PlotPoint point;
    point.label = map_size > 0 ? technique + " " + std::to_string(map_size) : technique;
    point.time_ms = number(p, i, "gpu_ms");
    point.error = number(p, i, "error");
    point.group = static_cast<int>(group - plots.families.begin());
    plots.by_scene[scene].push_back(point);
    // The same frame graded against the truth of a sun with a size: a plot of its own per size.
    if (!p.contains("light_sizes")) continue;
    const auto& sized = p.at("light_sizes");
    if (!sized.is_array()) throw std::runtime_error("point " + std::to_string(i) + ": \"light_sizes\" is not an array");
    for (const auto& entry : sized) {
      PlotPoint at_size = point;
      at_size.error = number(entry, i, "error");
      if (entry.contains("gpu_ms")) at_size.time_ms = number(entry, i, "gpu_ms");  // timed at that size
      plots.by_scene[sized_light_plot(scene, number(entry, i, "sun_deg"))].push_back(at_size);
    }
  }
  for (auto& [name, plot] : plots.by_scene) mark_pareto_front(plot);
  return plots;
}

BenchPlots load_bench_plots(const std::filesystem::path& file) {
  // A FIFO or a device would block or never end: refused before reading. A benchmark's results are a
  // few hundred kilobytes; 64 MiB is far beyond any real one.
  std::string text;
  try {
    text = platform::read_regular_file(file, 64u << 20);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(file.string() + ": cannot open the file: " + e.what());
  }
  try {
    BenchPlots plots = bench_plots_from_json(parse_json_bounded(text, JsonLimits{}));  // nesting bounded
    if (plots.by_scene.empty()) throw std::runtime_error("no points to plot");
    return plots;
  } catch (const JsonShapeError& e) {  // not JSON, or nested too deep
    throw std::runtime_error(file.string() + ": not valid JSON (" + std::string(e.what()) + ")");
  } catch (const nlohmann::json::exception& e) {  // a field of the wrong type
    throw std::runtime_error(file.string() + ": not valid JSON (" + printable(e.what(), 240) + ")");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file.string() + ": " + printable(e.what(), 400));
  }
}

void draw_bench_scene(const BenchPlots& plots, const std::string& scene, float width, float height) {
  const auto it = plots.by_scene.find(scene);
  static const std::vector<PlotPoint> none;
  draw_error_time_plot(it == plots.by_scene.end() ? none : it->second, plots.families, width, height,
                       ("scene: " + scene + "  (error against GPU ms per frame; front circled)").c_str());
}

bool draw_bench_window(const BenchPlots* plots, BenchPanelState& state, bool interactive) {
  if (!state.open) return false;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(std::max(450.0f, display.x - 660.0f), 40.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, display.x - 460.0f), std::min(520.0f, display.y - 60.0f)),
                           ImGuiCond_FirstUseEver);
  const bool visible = ImGui::Begin("Speed against error (shadowlab bench)", &state.open);
  bool load = false;
  if (visible) {
    if (interactive) {
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Load").x -
                              2 * ImGui::GetStyle().FramePadding.x - ImGui::GetStyle().ItemSpacing.x);
      load = ImGui::InputTextWithHint("##bench", "bench.json", &state.path, ImGuiInputTextFlags_EnterReturnsTrue);
      ImGui::SameLine();
      load |= ImGui::Button("Load");
    } else {
      ImGui::TextDisabled("%s", state.path.c_str());
    }
    if (!state.error.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextWrapped("%s", state.error.c_str());
      ImGui::PopStyleColor();
    }
    if (!plots) {
      ImGui::TextWrapped("No results loaded. Make some with: shadowlab bench --quick --out out/bench, then load "
                         "out/bench/bench.json.");
    } else {
      if (state.scene.empty() || !plots->by_scene.contains(state.scene)) state.scene = plots->by_scene.begin()->first;
      ImGui::SetNextItemWidth(200.0f);
      if (ImGui::BeginCombo("scene", state.scene.c_str())) {
        for (const auto& [name, points] : plots->by_scene)
          if (ImGui::Selectable(name.c_str(), name == state.scene)) state.scene = name;
        ImGui::EndCombo();
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Circled: the front, where nothing else is both faster and more exact");
      const ImVec2 avail = ImGui::GetContentRegionAvail();
      draw_bench_scene(*plots, state.scene, avail.x, std::max(200.0f, avail.y - ImGui::GetTextLineHeightWithSpacing()));
    }
  }
  ImGui::End();
  return load;
}

}  // namespace shadowlab
