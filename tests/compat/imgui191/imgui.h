// A compile-only stand-in for ImGui 1.91.9's <imgui.h> (the version vcpkg.json pins): the declarations
// app/imgui_gl.h uses, as imgui.h documents them from 1.91.4 on: ImTextureID is a 64-bit integer
// (`typedef ImU64 ImTextureID`, unless imconfig.h defines ImTextureID), no longer void*, and
// ImGui::Image takes that ID (1.91.9 dropped its tint and border parameters, which shadowlab does not
// pass). This machine has ImGui 1.86; tests/CMakeLists.txt compiles app/imgui_gl.h against this file
// (tests/compat/imgui_gl_imgui191.cpp). It is never linked or run.
#pragma once

#define IMGUI_VERSION "1.91.9 (compile-only stand-in)"
#define IMGUI_VERSION_NUM 19190

typedef unsigned long long ImU64;

#ifndef ImTextureID
typedef ImU64 ImTextureID;
#endif

struct ImVec2 {
  float x, y;
  constexpr ImVec2() : x(0.0f), y(0.0f) {}
  constexpr ImVec2(float x_, float y_) : x(x_), y(y_) {}
};

namespace ImGui {
void Image(ImTextureID user_texture_id, const ImVec2& image_size, const ImVec2& uv0 = ImVec2(0, 0),
           const ImVec2& uv1 = ImVec2(1, 1));
}  // namespace ImGui
