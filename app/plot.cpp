#include "app/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>
#include <imgui_internal.h>  // ImRect

namespace shadowlab {

void mark_pareto_front(std::vector<PlotPoint>& points) {
  for (auto& p : points) {
    p.pareto = std::none_of(points.begin(), points.end(), [&](const PlotPoint& q) {
      return (q.time_ms <= p.time_ms && q.error <= p.error) && (q.time_ms < p.time_ms || q.error < p.error);
    });
  }
}

std::vector<ImVec2> place_labels(const std::vector<ImVec2>& anchors, const std::vector<ImVec2>& sizes, ImVec2 min,
                                 ImVec2 max) {
  constexpr int kFarthestStep = 8;  // how many label heights a label may move up or down from its point
  std::vector<ImRect> placed;
  std::vector<ImVec2> out;
  for (std::size_t i = 0; i < anchors.size(); ++i) {
    const ImVec2 c = anchors[i], size = sizes[i];
    const float step = size.y + 2;
    // The four corners first, then further up and down on either side, nearest first.
    std::vector<ImVec2> candidates = {{c.x + 8, c.y - 16}, {c.x + 8, c.y + 4}, {c.x - 8 - size.x, c.y - 16},
                                      {c.x - 8 - size.x, c.y + 4}};
    for (int k = 1; k <= kFarthestStep; ++k)
      for (const float x : {c.x + 8, c.x - 8 - size.x}) {
        candidates.push_back({x, c.y - 16 - k * step});
        candidates.push_back({x, c.y + 4 + k * step});
      }
    ImRect where(candidates[0], ImVec2(candidates[0].x + size.x, candidates[0].y + size.y));
    for (const ImVec2& at : candidates) {
      const ImRect r(at, ImVec2(at.x + size.x, at.y + size.y));
      const bool inside = r.Min.x >= min.x && r.Max.x <= max.x && r.Min.y >= min.y && r.Max.y <= max.y;
      const bool free = std::none_of(placed.begin(), placed.end(), [&](const ImRect& q) { return q.Overlaps(r); });
      if (inside && free) {
        where = r;
        break;
      }
    }
    placed.push_back(where);
    out.push_back(where.Min);
  }
  return out;
}

namespace {

ImU32 group_color(int group) {
  static const ImU32 palette[] = {IM_COL32(90, 170, 255, 255), IM_COL32(255, 140, 60, 255), IM_COL32(110, 210, 110, 255),
                                  IM_COL32(230, 90, 200, 255), IM_COL32(240, 220, 80, 255), IM_COL32(160, 120, 255, 255),
                                  IM_COL32(80, 220, 210, 255),  IM_COL32(230, 80, 80, 255)};
  return palette[static_cast<std::size_t>(group) % (sizeof palette / sizeof palette[0])];
}

// Error spans decades (0.0001 to 0.5), so it is plotted on a log scale; zero errors sit on the floor.
constexpr double kErrorFloor = 1e-5;

// The front's labels at `anchors` (their points on screen), placed apart from each other inside p0-p1.
void draw_front_labels(ImDrawList* draw, const std::vector<const PlotPoint*>& front, const std::vector<ImVec2>& anchors,
                       ImVec2 p0, ImVec2 p1) {
  std::vector<ImVec2> sizes;
  for (const PlotPoint* p : front) sizes.push_back(ImGui::CalcTextSize(p->label.c_str()));
  const std::vector<ImVec2> at = place_labels(anchors, sizes, p0, p1);
  for (std::size_t i = 0; i < front.size(); ++i) {
    // A label moved away from its point (crowded fronts) gets a thin line back to it.
    const ImRect r(at[i], ImVec2(at[i].x + sizes[i].x, at[i].y + sizes[i].y));
    const ImVec2 nearest(std::clamp(anchors[i].x, r.Min.x, r.Max.x), std::clamp(anchors[i].y, r.Min.y, r.Max.y));
    const float dx = nearest.x - anchors[i].x, dy = nearest.y - anchors[i].y;
    if (dx * dx + dy * dy > 18.0f * 18.0f) draw->AddLine(anchors[i], nearest, IM_COL32(200, 200, 200, 160), 1.0f);
    draw->AddText(at[i], IM_COL32(255, 255, 255, 255), front[i]->label.c_str());
  }
}

// The legend: each group's colour and name, in the plot's top right corner.
void draw_legend(ImDrawList* draw, const std::vector<std::string>& group_names, ImVec2 p0, ImVec2 p1) {
  float y = p0.y + 6, widest = 0.0f;
  for (const auto& name : group_names) widest = std::max(widest, ImGui::CalcTextSize(name.c_str()).x);
  for (std::size_t g = 0; g < group_names.size(); ++g) {
    draw->AddCircleFilled(ImVec2(p1.x - widest - 18, y + 7), 4.0f, group_color(static_cast<int>(g)));
    draw->AddText(ImVec2(p1.x - widest - 8, y), IM_COL32(220, 220, 220, 255), group_names[g].c_str());
    y += 16;
  }
}

}  // namespace

void draw_error_time_plot(const std::vector<PlotPoint>& points, const std::vector<std::string>& group_names,
                          float width, float height, const char* title) {
  ImGui::TextUnformatted(title);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float left = 60.0f, bottom = 36.0f, top = 8.0f, right = 12.0f;
  const ImVec2 p0(origin.x + left, origin.y + top), p1(origin.x + width - right, origin.y + height - bottom);
  draw->AddRectFilled(p0, p1, IM_COL32(24, 26, 30, 255));
  draw->AddRect(p0, p1, IM_COL32(120, 120, 130, 255));
  if (points.empty()) {
    draw->AddText(ImVec2(p0.x + 10, p0.y + 10), IM_COL32(200, 200, 200, 255), "no data");
    ImGui::Dummy(ImVec2(width, height));
    return;
  }
  // Both axes are logarithmic: times span 1 to 1000 ms (a blurred 4096^2 map on llvmpipe) and errors
  // span decades; zero errors sit on the floor.
  double t_min = 1e30, t_max = 0.0, e_min = 1.0, e_max = kErrorFloor * 10;
  for (const auto& p : points) {
    t_min = std::min(t_min, std::max(p.time_ms, 0.01));
    t_max = std::max(t_max, p.time_ms);
    e_min = std::min(e_min, std::max(p.error, kErrorFloor));
    e_max = std::max(e_max, p.error);
  }
  const double lt_min = std::floor(std::log10(t_min)), lt_max = std::ceil(std::log10(std::max(t_max, t_min * 10)));
  const double lg_min = std::floor(std::log10(e_min)), lg_max = std::ceil(std::log10(e_max));
  auto to_screen = [&](double t, double e) {
    const double x = (std::log10(std::max(t, 0.01)) - lt_min) / std::max(lt_max - lt_min, 1.0);
    const double y = (std::log10(std::max(e, kErrorFloor)) - lg_min) / std::max(lg_max - lg_min, 1.0);
    return ImVec2(p0.x + static_cast<float>(x) * (p1.x - p0.x), p1.y - static_cast<float>(y) * (p1.y - p0.y));
  };
  char text[64];
  // Axes: decades of error and of time.
  for (double lg = lg_min; lg <= lg_max; lg += 1.0) {
    const ImVec2 a = to_screen(std::pow(10.0, lt_min), std::pow(10.0, lg));
    draw->AddLine(ImVec2(p0.x, a.y), ImVec2(p1.x, a.y), IM_COL32(60, 62, 70, 255));
    std::snprintf(text, sizeof text, "1e%d", static_cast<int>(lg));
    draw->AddText(ImVec2(origin.x + 8, a.y - 7), IM_COL32(200, 200, 200, 255), text);
  }
  for (double lt = lt_min; lt <= lt_max; lt += 1.0) {
    const ImVec2 a = to_screen(std::pow(10.0, lt), std::pow(10.0, lg_min));
    draw->AddLine(ImVec2(a.x, p0.y), ImVec2(a.x, p1.y), IM_COL32(60, 62, 70, 255));
    std::snprintf(text, sizeof text, "%g", std::pow(10.0, lt));
    const float w = ImGui::CalcTextSize(text).x;  // centred on its line, kept inside the plot's width
    draw->AddText(ImVec2(std::min(a.x - 0.5f * w, origin.x + width - w), p1.y + 4), IM_COL32(200, 200, 200, 255), text);
  }
  draw->AddText(ImVec2((p0.x + p1.x) * 0.5f - 50, p1.y + 18), IM_COL32(220, 220, 220, 255), "frame time (GPU ms, log)");
  // The front, joined in order of time, then every point, the front's labelled.
  std::vector<const PlotPoint*> front;
  for (const auto& p : points)
    if (p.pareto) front.push_back(&p);
  std::sort(front.begin(), front.end(), [](const PlotPoint* a, const PlotPoint* b) { return a->time_ms < b->time_ms; });
  for (std::size_t i = 1; i < front.size(); ++i)
    draw->AddLine(to_screen(front[i - 1]->time_ms, front[i - 1]->error), to_screen(front[i]->time_ms, front[i]->error),
                  IM_COL32(255, 255, 255, 200), 2.0f);
  for (const auto& p : points) {
    const ImVec2 c = to_screen(p.time_ms, p.error);
    draw->AddCircleFilled(c, p.pareto ? 5.0f : 3.5f, group_color(p.group));
    if (p.pareto) draw->AddCircle(c, 7.0f, IM_COL32(255, 255, 255, 255), 0, 1.5f);
  }
  // The front's labels, placed apart from each other.
  std::vector<ImVec2> anchors;
  for (const PlotPoint* p : front) anchors.push_back(to_screen(p->time_ms, p->error));
  draw_front_labels(draw, front, anchors, p0, p1);
  draw_legend(draw, group_names, p0, p1);
  draw->AddText(ImVec2(origin.x + 4, p0.y - 4 + (p1.y - p0.y) * 0.5f - 30), IM_COL32(220, 220, 220, 255), "error");
  ImGui::Dummy(ImVec2(width, height));
}

}  // namespace shadowlab
