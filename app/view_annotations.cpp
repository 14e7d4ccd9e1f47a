#include "app/view_annotations.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace shadowlab {

namespace {

ImU32 colour(const glm::vec3& c, float alpha = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.x, c.y, c.z, alpha));
}

constexpr ImU32 kText = IM_COL32(240, 240, 240, 255);
constexpr ImU32 kBackdrop = IM_COL32(0, 0, 0, 185);

ImVec2 text_size(float font_size, const std::string& text, float wrap = 0.0f) {
  return ImGui::GetFont()->CalcTextSizeA(font_size, FLT_MAX, wrap, text.c_str());
}

}  // namespace

float draw_colour_legend(ImDrawList* draw, const ColourLegend& legend, ImVec2 pos, float width, float font_size,
                         bool backdrop) {
  ImFont* font = ImGui::GetFont();
  const float pad = backdrop ? std::round(font_size * 0.4f) : 0.0f;
  const float inner = std::max(width - 2.0f * pad, 40.0f);
  const float small = std::round(font_size * 0.85f);
  // The box goes behind what is drawn after it: content on channel 1, the box on channel 0.
  if (draw) {
    draw->ChannelsSplit(2);
    draw->ChannelsSetCurrent(1);
  }
  float y = pos.y + pad;
  const float x = pos.x + pad;
  if (draw) draw->AddText(font, font_size, ImVec2(x, y), kText, legend.title.c_str());
  y += text_size(font_size, legend.title).y;
  if (draw) draw->AddText(font, small, ImVec2(x, y), IM_COL32(200, 200, 200, 255), legend.units.c_str(), nullptr, inner);
  y += text_size(small, legend.units, inner).y + 0.3f * font_size;
  if (!legend.ramp.empty()) {  // a categorical legend (the cascades) has swatches alone
    // The bar: the ramp's samples joined by gradients.
    const float bar = std::round(font_size * 1.1f);
    const std::size_t n = legend.ramp.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const float x0 = x + inner * static_cast<float>(i) / static_cast<float>(n - 1);
      const float x1 = x + inner * static_cast<float>(i + 1) / static_cast<float>(n - 1);
      const ImU32 a = colour(legend.ramp[i]), b = colour(legend.ramp[i + 1]);
      if (draw) draw->AddRectFilledMultiColor(ImVec2(x0, y), ImVec2(x1 + 0.5f, y + bar), a, b, b, a);
    }
    if (draw) draw->AddRect(ImVec2(x - 1, y - 1), ImVec2(x + inner + 1, y + bar + 1), IM_COL32(255, 255, 255, 200));
    // Tick marks at the ends and inside, the values under them.
    const float tick = std::round(font_size * 0.35f), bar_bottom = y + bar;
    auto mark = [&](float t) {
      const float at = x + inner * std::clamp(t, 0.0f, 1.0f);
      if (draw) draw->AddLine(ImVec2(at, bar_bottom), ImVec2(at, bar_bottom + tick), kText, 2.0f);
      return at;
    };
    mark(0.0f);
    mark(1.0f);
    y += bar + tick;
    const ImVec2 low = text_size(font_size, legend.low), high = text_size(font_size, legend.high);
    const bool high_below = low.x + high.x + font_size > inner;  // no room on one line: the high end below
    if (draw) draw->AddText(font, font_size, ImVec2(x, y), kText, legend.low.c_str());
    for (const auto& [t, text] : legend.ticks) {
      const float at = mark(t);
      const float w = text_size(font_size, text).x;
      const float left = std::clamp(at - 0.5f * w, x + low.x + 0.5f * font_size, std::max(x + inner - w, x));
      const bool room = high_below || left + w < x + inner - high.x - 0.5f * font_size;
      if (draw && room) draw->AddText(font, font_size, ImVec2(left, y), kText, text.c_str());
    }
    if (high_below) y += low.y;
    if (draw) draw->AddText(font, font_size, ImVec2(x + inner - high.x, y), kText, legend.high.c_str());
    y += high.y + 0.25f * font_size;
  }
  // Colours outside the ramp, each a square and its meaning, wrapped onto more rows when needed.
  float sx = x;
  for (const auto& [c, text] : legend.swatches) {
    const float w = small + 0.4f * small + text_size(small, text).x + small;
    if (sx > x && sx + w > x + inner) {
      sx = x;
      y += small * 1.3f;
    }
    if (draw) draw->AddRectFilled(ImVec2(sx, y + 0.1f * small), ImVec2(sx + small, y + 1.1f * small), colour(c));
    if (draw) draw->AddRect(ImVec2(sx, y + 0.1f * small), ImVec2(sx + small, y + 1.1f * small), IM_COL32(255, 255, 255, 160));
    if (draw) draw->AddText(font, small, ImVec2(sx + 1.4f * small, y), kText, text.c_str());
    sx += w;
  }
  if (!legend.swatches.empty()) y += small * 1.3f;
  y += pad;
  if (draw) {
    draw->ChannelsSetCurrent(0);
    if (backdrop) draw->AddRectFilled(pos, ImVec2(pos.x + width, y), kBackdrop, 0.3f * font_size);
    draw->ChannelsMerge();
  }
  return y - pos.y;
}

void draw_view_annotations(const DebugAnnotations& annotations, int fb_width, int fb_height, float x_begin, float x_end) {
  if (annotations.quads.empty() && annotations.legends.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplaySize.x / static_cast<float>(std::max(fb_width, 1));
  const float sy = io.DisplaySize.y / static_cast<float>(std::max(fb_height, 1));
  const float font_size = std::round(ImGui::GetFontSize() * kAnnotationTextScale);
  ImFont* font = ImGui::GetFont();
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->PushClipRect(ImVec2(x_begin, 0.0f), ImVec2(x_end, io.DisplaySize.y), true);
  // Each label above its quad, wrapped to the quad's width, so that it hides nothing of the map; inside
  // the quad's top where another quad stands right above it (a cube map's lower row). The highest label
  // bounds the legends.
  auto rect = [&](const DebugQuadLabel& q) {  // left, top, right, bottom in display coordinates
    return ImVec4(static_cast<float>(q.x) * sx, static_cast<float>(fb_height - q.y - q.height) * sy,
                  static_cast<float>(q.x + q.width) * sx, static_cast<float>(fb_height - q.y) * sy);
  };
  float labels_top = io.DisplaySize.y;
  for (const DebugQuadLabel& q : annotations.quads) {
    const ImVec4 r = rect(q);
    bool quad_above = false;
    for (const DebugQuadLabel& other : annotations.quads) {
      const ImVec4 o = rect(other);
      quad_above |= &other != &q && o.x < r.z && r.x < o.z && o.w <= r.y && o.w > r.y - 2.0f * font_size;
    }
    const float pad = std::round(0.2f * font_size);
    const float wrap = std::max(r.z - r.x - 2.0f * pad, font_size);
    const ImVec2 size = text_size(font_size, q.text, wrap);
    const float top = quad_above ? r.y : r.y - 2.0f - size.y - 2.0f * pad;
    labels_top = std::min(labels_top, top);
    draw->AddRectFilled(ImVec2(r.x, top), ImVec2(r.x + std::min(r.z - r.x, size.x + 2.0f * pad), top + size.y + 2.0f * pad),
                        kBackdrop, 0.2f * font_size);
    draw->AddText(font, font_size, ImVec2(r.x + pad, top + pad), kText, q.text.c_str(), nullptr, wrap);
  }
  // Legends from the bottom right up, above the quads and their labels (or the bottom edge), about 40
  // characters wide, narrower when this part of the view is.
  const float margin = std::round(0.5f * font_size);
  const float width = std::min(22.0f * font_size, x_end - x_begin - 2.0f * margin);
  float bottom = (annotations.quads.empty() ? io.DisplaySize.y - 2.5f * font_size : labels_top) - margin;
  for (const ColourLegend& legend : annotations.legends) {
    const float height = draw_colour_legend(nullptr, legend, ImVec2(0.0f, 0.0f), width, font_size, true);  // measured
    bottom -= height;
    draw_colour_legend(draw, legend, ImVec2(x_end - margin - width, bottom), width, font_size, true);
    bottom -= margin;
  }
  draw->PopClipRect();
}

}  // namespace shadowlab
