#include "app/ui_fonts.h"

#include <algorithm>
#include <cmath>
#include <system_error>

#include <imgui.h>

namespace shadowlab {

namespace fs = std::filesystem;

UiScale plan_ui_scale(float content_scale, float pixels_per_point, float text_size) {
  auto sane = [](float v) { return std::isfinite(v) && v > 0.25f && v < 8.0f ? v : 1.0f; };
  content_scale = sane(content_scale);
  pixels_per_point = sane(pixels_per_point);
  text_size = std::clamp(sane(text_size), 0.5f, 3.0f);
  UiScale s;
  if (pixels_per_point > 1.01f) {  // macOS Retina: points, with more pixels behind each
    s.raster = text_size * pixels_per_point;
    s.font_global = 1.0f / pixels_per_point;
    s.style = text_size;
  } else {
    s.raster = text_size * content_scale;
    s.style = text_size * content_scale;
  }
  return s;
}

UiFonts build_ui_fonts(ImFontAtlas& atlas, const fs::path& folder, float raster, std::string* warning) {
  atlas.Clear();
  const float px = std::round(kBaseFontPixels * raster);
  // Latin-1 plus the punctuation and symbols lab texts use (dashes, quotes, ellipsis, arrows, <=, >=).
  static const ImWchar ranges[] = {0x0020, 0x00FF, 0x2010, 0x2027, 0x2190, 0x2193, 0x2212, 0x2212,
                                   0x2248, 0x2248, 0x2260, 0x2265, 0x03B1, 0x03C9, 0};
  std::string missing;
  auto load = [&](const char* file, float size) -> ImFont* {
    const fs::path path = folder / file;
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) {
      ImFontConfig config;
      config.OversampleH = 2;
      config.OversampleV = 1;
      config.PixelSnapH = true;
      // The path as UTF-8, which ImGui opens with the platform's wide-character call on Windows.
      const std::u8string utf8 = path.u8string();
      if (ImFont* f = atlas.AddFontFromFileTTF(reinterpret_cast<const char*>(utf8.c_str()), size, &config, ranges))
        return f;
    }
    if (missing.find(file) == std::string::npos) missing += (missing.empty() ? "" : ", ") + std::string(file);
    ImFontConfig config;
    config.SizePixels = std::round(13.0f * raster);  // ProggyClean's own size, scaled
    return atlas.AddFontDefault(&config);
  };
  UiFonts fonts;
  fonts.body = load("DejaVuSans.ttf", px);  // the first font is ImGui's default
  fonts.bold = load("DejaVuSans-Bold.ttf", px);
  fonts.italic = load("DejaVuSans-Oblique.ttf", px);
  fonts.mono = load("DejaVuSansMono.ttf", px);
  fonts.h1 = load("DejaVuSans-Bold.ttf", std::round(px * 1.6f));
  fonts.h2 = load("DejaVuSans-Bold.ttf", std::round(px * 1.3f));
  fonts.h3 = load("DejaVuSans-Bold.ttf", std::round(px * 1.12f));
  fonts.caption = load("DejaVuSans-Bold.ttf", std::round(px * 2.6f));
  fonts.caption_text = load("DejaVuSans.ttf", std::round(px * 1.7f));
  fonts.builtin = !missing.empty();
  if (warning) *warning = missing.empty() ? "" : "fonts not found in " + folder.string() + " (" + missing + "): ImGui's built-in font is used";
  atlas.Build();
  return fonts;
}

void apply_ui_style(const UiScale& scale) {
  ImGuiStyle& style = ImGui::GetStyle();
  style = ImGuiStyle();
  ImGui::StyleColorsDark(&style);
  style.ScaleAllSizes(scale.style);
  ImGui::GetIO().FontGlobalScale = scale.font_global;
}

}  // namespace shadowlab
