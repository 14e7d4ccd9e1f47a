// app/imgui_gl.h compiled (never linked or run) against the stand-in tests/compat/imgui191: ImGui 1.91.9,
// where ImTextureID is ImU64 and the OpenGL3 backend still leaves the atlas texture to the application.
#include <type_traits>

#include "app/imgui_gl.h"

static_assert(IMGUI_VERSION_NUM >= 19140 && IMGUI_VERSION_NUM < 19200,
              "the stand-in header must be found before the real imgui.h");
static_assert(std::is_same_v<ImTextureID, ImU64>);

namespace shadowlab {

void every_gl_call_of_the_seam(unsigned gl_name) {
  gl_image(gl_name, ImVec2(64, 64));
  gl_image(gl_name, ImVec2(64, 64), ImVec2(0, 1), ImVec2(1, 0));
  remake_font_texture();
  drop_font_texture();
}

}  // namespace shadowlab
