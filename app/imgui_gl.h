// The window's OpenGL side of ImGui: a GL texture shown as an image, and the font atlas's texture made
// again after the fonts change. The one place that knows how ImGui changed these (app/keys.h is the
// same for the key API):
//   1.91.4  ImTextureID became a 64-bit integer (ImU64) instead of void*, so a GL name cast to a
//           pointer and then to ImTextureID no longer compiles;
//   1.92    ImGui::Image takes an ImTextureRef (made from an ImTextureID), and the OpenGL3 backend
//           creates and updates the atlas texture itself (IMGUI_HAS_TEXTURES,
//           ImGuiBackendFlags_RendererHasTextures): ImGui_ImplOpenGL3_CreateFontsTexture and
//           DestroyFontsTexture are gone.
// Supported: ImGui 1.86 (Debian 12: built and run here) to 1.92 (the program as a whole: to 1.91.9, which
// vcpkg.json pins; README, Platforms). Compiled, never linked or run, against stand-ins of 1.91.9's and
// 1.92's declarations (tests/compat/imgui191, tests/compat/imgui192; targets imgui191_gl_check and
// imgui192_seam_check), written from ImGui's imgui.h and its changelog.
#pragma once

#include <cstdint>
#include <type_traits>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

namespace shadowlab {

namespace imgui_detail {
// A template, so that only the branch of this build's ImTextureID (void* before 1.91.4, ImU64 after,
// or whatever imconfig.h defines) is instantiated.
template <typename Id>
Id texture_id_as(unsigned gl_name) {
  if constexpr (std::is_pointer_v<Id>)
    return reinterpret_cast<Id>(static_cast<std::uintptr_t>(gl_name));
  else
    return static_cast<Id>(gl_name);
}
}  // namespace imgui_detail

// The OpenGL texture name `gl_name` as ImGui's texture ID.
inline ImTextureID gl_texture_id(unsigned gl_name) { return imgui_detail::texture_id_as<ImTextureID>(gl_name); }

// ImGui::Image of the OpenGL texture `gl_name`.
inline void gl_image(unsigned gl_name, const ImVec2& size, const ImVec2& uv0 = ImVec2(0, 0),
                     const ImVec2& uv1 = ImVec2(1, 1)) {
  ImGui::Image(gl_texture_id(gl_name), size, uv0, uv1);
}

// After the font atlas was built again between frames: the backend's atlas texture made from it now.
// From 1.92 on the backend sees the changed atlas and updates its texture itself.
inline void remake_font_texture() {
#if !defined(IMGUI_HAS_TEXTURES)
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
#endif
}

// The same, left to the backend's next ImGui_ImplOpenGL3_NewFrame (which makes a missing atlas texture).
inline void drop_font_texture() {
#if !defined(IMGUI_HAS_TEXTURES)
  ImGui_ImplOpenGL3_DestroyFontsTexture();
#endif
}

}  // namespace shadowlab
