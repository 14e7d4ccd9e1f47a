// Error-against-time scatter plot with the Pareto front, drawn with ImGui's draw lists: the same code
// draws it in the app's panel and, through ImGuiOffscreen, into the benchmark's pareto.png.
#pragma once

#include <string>
#include <vector>

#include <imgui.h>

namespace shadowlab {

struct PlotPoint {
  std::string label;  // e.g. "pcf5 1024"
  double time_ms = 0.0;
  double error = 0.0;
  bool pareto = false;
  int group = 0;  // colour group (technique)
};

// Marks the points no other point beats in both time and error (lower is better in both).
void mark_pareto_front(std::vector<PlotPoint>& points);

// Where to put labels of the given sizes next to their anchors (top-left corners): above right of the
// anchor, else the first other corner (below right, above left, below left), else further up or down
// on either side (up to 8 label heights, nearest first), that stays inside [min, max] and overlaps no
// label placed before; when none does, above right.
std::vector<ImVec2> place_labels(const std::vector<ImVec2>& anchors, const std::vector<ImVec2>& sizes, ImVec2 min,
                                 ImVec2 max);

// Draws into the current ImGui window: log-scaled error (y) against time (x), the front joined and its
// points labelled. `group_names` names the colours in a legend.
void draw_error_time_plot(const std::vector<PlotPoint>& points, const std::vector<std::string>& group_names,
                          float width, float height, const char* title);

}  // namespace shadowlab
