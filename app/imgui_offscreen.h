// Dear ImGui drawn into a framebuffer object instead of a window, so headless commands produce the same
// pictures the app's panel shows (the benchmark's plot, documentation screenshots). Needs a current GL
// context (EGL headless or the window's); uses only ImGui's OpenGL3 backend, no platform backend.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "app/ui_fonts.h"

namespace shadowlab {

class ImGuiOffscreen {
 public:
  ImGuiOffscreen(int width, int height);
  ~ImGuiOffscreen();
  ImGuiOffscreen(const ImGuiOffscreen&) = delete;
  ImGuiOffscreen& operator=(const ImGuiOffscreen&) = delete;

  // Runs `draw` (ImGui calls) for a few frames so windows settle their sizes, renders the last frame over
  // a background (either cleared, or `background` RGBA8 top row first, width x height) and returns RGBA8
  // pixels, top row first.
  std::vector<std::uint8_t> render(const std::function<void()>& draw, const std::vector<std::uint8_t>* background = nullptr);

  // Loads the panel's fonts from `folder` and scales the style, as the window does for a monitor of
  // that scale. Call before render(). A missing font file falls back to ImGui's own font, with a warning
  // on stderr.
  UiFonts use_fonts(const std::filesystem::path& folder, const UiScale& scale);

 private:
  int width_, height_;
  void* context_;  // ImGuiContext*, kept opaque so this header needs no ImGui
  void* previous_context_;
};

}  // namespace shadowlab
