// A compile-only stand-in for ImGui 1.92's backends/imgui_impl_opengl3.h. 1.92 removed
// ImGui_ImplOpenGL3_CreateFontsTexture and ImGui_ImplOpenGL3_DestroyFontsTexture: the backend updates
// its textures in RenderDrawData, through the one call declared here, which app/imgui_gl.h does not make.
#pragma once

#include "imgui.h"

void ImGui_ImplOpenGL3_UpdateTexture(ImTextureData* tex);
