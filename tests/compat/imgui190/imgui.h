// A compile-only stand-in for ImGui 1.89+'s <imgui.h> (Ubuntu 24.04 and Debian 13 ship 1.90): the
// declarations app/keys.h uses, as imgui.h documents them from 1.89 on: ImGuiKey a typed enum
// (`enum ImGuiKey : int`, every key named, ImGuiKey_0 to ImGuiKey_9 and ImGuiKey_F1 to F12 in a row) and
// `bool ImGui::IsKeyPressed(ImGuiKey key, bool repeat = true)` with no int overload, so a GLFW key code
// no longer converts. This machine has ImGui 1.86; tests/CMakeLists.txt compiles app/keys.h's 1.87+
// branch against this file (tests/compat/keys_imgui190.cpp). It is never linked or run.
#pragma once

#define IMGUI_VERSION "1.90 (compile-only stand-in)"
#define IMGUI_VERSION_NUM 19000

enum ImGuiKey : int {
  ImGuiKey_None = 0,
  ImGuiKey_Tab = 512,
  ImGuiKey_PageUp,
  ImGuiKey_PageDown,
  ImGuiKey_0,
  ImGuiKey_1,
  ImGuiKey_2,
  ImGuiKey_3,
  ImGuiKey_4,
  ImGuiKey_5,
  ImGuiKey_6,
  ImGuiKey_7,
  ImGuiKey_8,
  ImGuiKey_9,
  ImGuiKey_H,
  ImGuiKey_M,
  ImGuiKey_N,
  ImGuiKey_P,
  ImGuiKey_R,
  ImGuiKey_S,
  ImGuiKey_T,
  ImGuiKey_F1,
  ImGuiKey_F2,
  ImGuiKey_F3,
  ImGuiKey_F4,
  ImGuiKey_F5,
  ImGuiKey_F6,
  ImGuiKey_F7,
  ImGuiKey_F8,
  ImGuiKey_F9,
  ImGuiKey_F10,
  ImGuiKey_F11,
  ImGuiKey_F12,
};

namespace ImGui {
bool IsKeyPressed(ImGuiKey key, bool repeat = true);
}  // namespace ImGui
