// A compile-only stand-in for ImGui 1.92's <imgui.h>: the declarations app/imgui_gl.h and app/keys.h
// use, as imgui.h documents them (written from 1.92.3's header and the 1.92.0 changelog):
// - IMGUI_HAS_TEXTURES: the renderer backend creates and updates textures itself
//   (ImGuiBackendFlags_RendererHasTextures), so the application no longer makes the atlas texture;
// - ImTextureID a 64-bit integer (since 1.91.4), and ImGui::Image taking an ImTextureRef, which is made
//   from an ImTextureID (or, unless IMGUI_DISABLE_OBSOLETE_FUNCTIONS, from a legacy void*);
// - the keys as since 1.89: a typed `enum ImGuiKey : int`, ImGuiKey_0 to ImGuiKey_9 in a row, and
//   `bool IsKeyPressed(ImGuiKey key, bool repeat = true)` with no int overload.
// This machine has ImGui 1.86; tests/CMakeLists.txt compiles app/imgui_gl.h and app/keys.h against this
// file (tests/compat/imgui_seam_imgui192.cpp). It is never linked or run.
#pragma once

#define IMGUI_VERSION "1.92.3 (compile-only stand-in)"
#define IMGUI_VERSION_NUM 19230
#define IMGUI_HAS_TEXTURES

typedef unsigned long long ImU64;
struct ImTextureData;

#ifndef ImTextureID
typedef ImU64 ImTextureID;
#endif

struct ImVec2 {
  float x, y;
  constexpr ImVec2() : x(0.0f), y(0.0f) {}
  constexpr ImVec2(float x_, float y_) : x(x_), y(y_) {}
};

struct ImTextureRef {
  ImTextureRef() : _TexData(nullptr), _TexID(0) {}
  ImTextureRef(ImTextureID tex_id) : _TexData(nullptr), _TexID(tex_id) {}
#if !defined(IMGUI_DISABLE_OBSOLETE_FUNCTIONS) && !defined(ImTextureID)
  ImTextureRef(void* tex_id) : _TexData(nullptr), _TexID(reinterpret_cast<ImU64>(tex_id)) {}
#endif
  ImTextureData* _TexData;
  ImTextureID _TexID;
};

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
void Image(ImTextureRef tex_ref, const ImVec2& image_size, const ImVec2& uv0 = ImVec2(0, 0),
           const ImVec2& uv1 = ImVec2(1, 1));
bool IsKeyPressed(ImGuiKey key, bool repeat = true);
}  // namespace ImGui
