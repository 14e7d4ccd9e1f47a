// What the window draws over the view (the hint after H, demo mode's caption, F12's answer) and its
// screenshots.
#include "app/window_app.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>

#include "renderer/gl.h"  // before GLFW, so GLFW does not include a GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "core/image_io.h"
#include "core/platform.h"
#include "core/untrusted.h"

namespace shadowlab {

// For a few seconds after the panel is hidden, one line in the corner says how to get it back; then
// nothing is drawn over the view.
void draw_hidden_hint(const WindowApp& app) {
  constexpr double kHintSeconds = 3.0;
  if (glfwGetTime() - app.hidden_since > kHintSeconds) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(10.0f, display.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##panel hidden", nullptr, flags)) ImGui::TextUnformatted("Panel hidden: press H to show it");
  ImGui::End();
}

namespace {

// Where F12 saves: $SHADOWLAB_SCREENSHOTS, else a shadowlab folder in the user's pictures folder (see
// platform::user_pictures_folder), else (no home folder) the working folder. Not the working folder
// first: a window started from a launcher or an IDE has one the user never sees (the build folder, /).
std::filesystem::path screenshot_folder() {
  if (std::filesystem::path p = platform::env_path("SHADOWLAB_SCREENSHOTS"); !p.empty()) return p;
  const std::filesystem::path pictures = platform::user_pictures_folder();
  return pictures.empty() ? std::filesystem::current_path() : pictures / "shadowlab";
}

// A new file there, made with its folder: shadowlab-lab01-20261127-201501.png (-2, -3... within a second).
std::filesystem::path new_screenshot_file(int lab) {
  const std::filesystem::path folder = std::filesystem::absolute(screenshot_folder());
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw std::runtime_error(folder.string() + ": cannot create the screenshot folder" + (ec ? ": " + ec.message() : std::string()));
  char stem[64];
  const std::tm now = platform::local_time(std::time(nullptr));
  const int used = std::snprintf(stem, sizeof stem, "shadowlab-lab%02d-", lab);
  std::strftime(stem + used, sizeof stem - static_cast<std::size_t>(used), "%Y%m%d-%H%M%S", &now);
  for (int n = 1; n < 1000; ++n) {
    const std::filesystem::path path = folder / (std::string(stem) + (n > 1 ? "-" + std::to_string(n) : "") + ".png");
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return path;
  }
  throw std::runtime_error(folder.string() + ": no free name for a screenshot");
}

}  // namespace

void save_screenshot(WindowApp& app, int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  flip_rows(rgba, width, height, 4);
  // A path given by --screenshot or a script is the caller's: written there, nothing shown over the view.
  if (!app.screenshot_path.empty()) {
    try {
      write_png(app.screenshot_path, width, height, rgba);
      app.status = "saved " + std::filesystem::absolute(app.screenshot_path).string();
    } catch (const std::exception& e) {
      app.status = e.what();
    }
    return;
  }
  // F12 or the panel's button: a new file in the screenshot folder, and its full path over the view.
  app.toast_since = glfwGetTime();
  try {
    const std::filesystem::path path = new_screenshot_file(app.lab->number);
    write_png(path, width, height, rgba);
    const std::u8string utf8 = path.u8string();  // ImGui's text is UTF-8; a Windows path is wide
    const std::string shown(reinterpret_cast<const char*>(utf8.c_str()));
    app.status = "saved " + shown;
    app.toast = "Screenshot saved to " + shown;
    app.toast_error = false;
    std::printf("shadowlab: screenshot saved to %s\n", shown.c_str());
    std::fflush(stdout);
  } catch (const std::exception& e) {
    app.status = e.what();
    app.toast = "Screenshot not saved: " + shortened(printable(e.what(), kFullErrorBytes), kPanelErrorBytes);
    app.toast_error = true;
    std::fprintf(stderr, "shadowlab: screenshot not saved: %s\n", e.what());
  }
}

// Demo mode's caption: the chosen preset's name and what it shows, large enough to read from the back of a
// lecture hall, centred at the top of the view right of the panel, while its values hold.
void draw_caption(const WindowApp& app) {
  const Preset* preset = app.preset_shown();
  if (!preset) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float left = app.panel_hidden ? 0.0f : std::min(app.panel_right, display.x * 0.5f);
  const float width = display.x - left;
  const float top = app.pass_line_shown() ? ImGui::GetFrameHeight() + 16.0f : 10.0f;  // under the pass-time line
  ImGui::SetNextWindowPos(ImVec2(left + width * 0.5f, top), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(width - 20.0f, display.y * 0.5f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("##caption", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::PushTextWrapPos(width - 40.0f);
  std::string place;
  try {
    const auto order = story_order(*app.lab);
    const auto at = std::find(order.begin(), order.end(), *app.shown_preset);
    if (at != order.end()) place = "  " + std::to_string(at - order.begin() + 1) + "/" + std::to_string(order.size());
  } catch (const std::invalid_argument&) {
  }
  if (app.fonts.caption) ImGui::PushFont(app.fonts.caption);
  ImGui::TextUnformatted(preset->name.c_str());
  if (app.fonts.caption) ImGui::PopFont();
  if (app.fonts.caption_text) ImGui::PushFont(app.fonts.caption_text);
  if (!place.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("Lab %d%s", app.lab->number, place.c_str());
  }
  ImGui::TextUnformatted(preset->description.c_str());
  if (app.impl == Impl::Exercise && needs_working_exercise(*app.lab, *preset))
    ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.45f, 1.0f), "Your exercise shows %s once it works; the solution's picture: \"Solution beside it\" in the panel",
                       preset->artifact.provokes.c_str());
  if (app.fonts.caption_text) ImGui::PopFont();
  ImGui::PopTextWrapPos();
  ImGui::End();
}

// F12's answer over the view for a few seconds, at the bottom centre (over the view, in front of the panel).
void draw_toast(const WindowApp& app) {
  constexpr double kToastSeconds = 5.0;
  if (app.toast.empty() || glfwGetTime() - app.toast_since > kToastSeconds) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - 10.0f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::PushTextWrapPos(display.x * 0.8f);  // a long path wraps rather than leaving the window
  ImGui::Begin("##screenshot", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  if (app.toast_error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
  ImGui::TextUnformatted(app.toast.c_str());
  if (app.toast_error) ImGui::PopStyleColor();
  ImGui::End();
  ImGui::PopTextWrapPos();
}

}  // namespace shadowlab
