// The window's keys, read from ImGui's key state. The one place that knows ImGui's key API changed:
// 1.86 (Debian 12) indexes keys by the platform backend's codes (GLFW_KEY_F12); 1.87 named every key
// (ImGuiKey_F12) and 1.89 made ImGuiKey a strongly typed enum, so GLFW codes no longer compile there
// (Ubuntu 24.04 and Debian 13 ship 1.90). Built here against 1.86; the 1.87+ branch follows ImGui's
// documented API (imgui.h, ImGuiKey_; ocornut/imgui#4921) and is compiled against stand-ins of 1.90's
// and 1.92's declarations (tests/compat/imgui190, tests/compat/imgui192). Supported: 1.86 to 1.92; the
// OpenGL side of the seam (texture IDs, the font texture) is app/imgui_gl.h.
#pragma once

#include <imgui.h>

#if IMGUI_VERSION_NUM < 18700
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define SHADOWLAB_KEY(named, glfw) (glfw)
#else
#define SHADOWLAB_KEY(named, glfw) (named)
#endif

namespace shadowlab {

enum class Key { F11, F12, N, P, S, M, H, T, R, PageUp, PageDown };

inline bool key_pressed(Key key, bool repeat = false) {
  switch (key) {
    case Key::F11: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_F11, GLFW_KEY_F11), repeat);
    case Key::F12: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_F12, GLFW_KEY_F12), repeat);
    case Key::N: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_N, GLFW_KEY_N), repeat);
    case Key::P: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_P, GLFW_KEY_P), repeat);
    case Key::S: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_S, GLFW_KEY_S), repeat);
    case Key::M: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_M, GLFW_KEY_M), repeat);
    case Key::H: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_H, GLFW_KEY_H), repeat);
    case Key::T: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_T, GLFW_KEY_T), repeat);
    case Key::R: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_R, GLFW_KEY_R), repeat);
    case Key::PageUp: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_PageUp, GLFW_KEY_PAGE_UP), repeat);
    case Key::PageDown: return ImGui::IsKeyPressed(SHADOWLAB_KEY(ImGuiKey_PageDown, GLFW_KEY_PAGE_DOWN), repeat);
  }
  return false;
}

// The digit keys 0-9 of the main keyboard.
inline bool digit_pressed(int digit) {
  if (digit < 0 || digit > 9) return false;
  return ImGui::IsKeyPressed(SHADOWLAB_KEY(static_cast<ImGuiKey>(ImGuiKey_0 + digit), GLFW_KEY_0 + digit), false);
}

// The function keys F1-F10 (F11 and F12 are Key::F11, Key::F12): n from 1 to 10.
inline bool function_key_pressed(int n) {
  if (n < 1 || n > 10) return false;
  return ImGui::IsKeyPressed(SHADOWLAB_KEY(static_cast<ImGuiKey>(ImGuiKey_F1 + n - 1), GLFW_KEY_F1 + n - 1), false);
}

}  // namespace shadowlab

#undef SHADOWLAB_KEY
