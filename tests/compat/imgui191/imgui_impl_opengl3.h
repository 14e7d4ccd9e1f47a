// A compile-only stand-in for ImGui 1.91.9's backends/imgui_impl_opengl3.h: the two calls
// app/imgui_gl.h makes there (the atlas texture, made and dropped by the application up to 1.91).
#pragma once

#include "imgui.h"

bool ImGui_ImplOpenGL3_CreateFontsTexture();
void ImGui_ImplOpenGL3_DestroyFontsTexture();
