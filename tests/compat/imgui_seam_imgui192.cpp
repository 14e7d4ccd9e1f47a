// app/imgui_gl.h and app/keys.h compiled (never linked or run) against the stand-in tests/compat/imgui192:
// ImGui 1.92, where ImGui::Image takes an ImTextureRef and the OpenGL3 backend has no font-texture calls.
#include <initializer_list>
#include <type_traits>

#include "tests/compat/imgui_gl_calls.h"
#include "app/keys.h"

static_assert(IMGUI_VERSION_NUM >= 19200, "the stand-in header must be found before the real imgui.h");
static_assert(std::is_same_v<ImTextureID, ImU64>);

namespace shadowlab {

bool any_key_of_the_window_pressed() {
  bool any = false;
  for (Key k : {Key::F11, Key::F12, Key::N, Key::P, Key::S, Key::M, Key::H, Key::T, Key::PageUp, Key::PageDown})
    any |= key_pressed(k);
  for (int digit = 0; digit <= 9; ++digit) any |= digit_pressed(digit);
  return any;
}

}  // namespace shadowlab
