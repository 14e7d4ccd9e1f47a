// The panel's fonts and sizes. DejaVu Sans (regular, bold, oblique) and DejaVu Sans Mono, shipped in
// assets/fonts, rasterised at the size the screen needs; ImGui's built-in font in every role when the
// files are missing.
//
// Scale: on Windows and Linux (X11, Wayland through XWayland) a window's coordinates are pixels and a
// monitor's content scale says how large text must be (1 at 96 dpi, 2 on a 4K laptop at "200 %"), so
// fonts are rasterised at kBaseFontPixels x content scale x the user's text size and every style size
// (padding, spacing, rounding) is scaled by the same factor. On macOS a window's coordinates are points
// and the framebuffer holds 2 pixels per point on a Retina display: the fonts are then rasterised at
// twice the size and drawn at half scale (io.FontGlobalScale), so they are sharp, while the style is
// scaled by the user's text size alone. plan_ui_scale() decides which, from what GLFW reports.
#pragma once

#include <filesystem>
#include <string>

struct ImFont;
struct ImFontAtlas;

namespace shadowlab {

constexpr float kBaseFontPixels = 15.0f;

struct UiFonts {
  ImFont* body = nullptr;
  ImFont* bold = nullptr;
  ImFont* italic = nullptr;
  ImFont* mono = nullptr;
  ImFont* h1 = nullptr;  // headings: bold at 1.6, 1.3 and 1.12 x the body size
  ImFont* h2 = nullptr;
  ImFont* h3 = nullptr;
  ImFont* caption = nullptr;       // demo mode's caption over the view: bold at 2.6 x, its text at 1.7 x
  ImFont* caption_text = nullptr;  // (39 and 26 pixels at 100 %: read from the back of a lecture hall)
  bool builtin = false;  // the files were missing: ImGui's own font in every role
};

// How to build fonts and style for a window.
struct UiScale {
  float raster = 1.0f;       // fonts are rasterised at kBaseFontPixels x raster
  float font_global = 1.0f;  // io.FontGlobalScale: 1, or 1 / pixels per point on macOS
  float style = 1.0f;        // ImGuiStyle::ScaleAllSizes factor
};

// content_scale: glfwGetWindowContentScale's x; pixels_per_point: framebuffer width / window width
// (1 except on macOS Retina); text_size: the user's control, 1 = 100 %.
UiScale plan_ui_scale(float content_scale, float pixels_per_point, float text_size);

// Clears `atlas` and loads the fonts from `folder` (assets/fonts) at kBaseFontPixels x raster. When a
// file is missing or unreadable, ImGui's default font is used in its place and `warning` (if given)
// names the file. The caller recreates the GPU texture (app/imgui_gl.h).
UiFonts build_ui_fonts(ImFontAtlas& atlas, const std::filesystem::path& folder, float raster, std::string* warning = nullptr);

// Resets the current ImGui context's style to the dark theme at ImGui's default sizes, then scales it.
void apply_ui_style(const UiScale& scale);

}  // namespace shadowlab
