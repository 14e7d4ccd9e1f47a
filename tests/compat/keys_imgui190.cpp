// app/keys.h's branch for ImGui 1.87 and later, compiled (never linked or run) against the stand-in
// tests/compat/imgui190/imgui.h: every key of the window, the digits and F1-F10 go through it.
#include <initializer_list>

#include "app/keys.h"

static_assert(IMGUI_VERSION_NUM >= 18700, "the stand-in header must be found before the real imgui.h");

namespace shadowlab {

bool any_key_of_the_window_pressed() {
  bool any = false;
  for (Key k : {Key::F11, Key::F12, Key::N, Key::P, Key::S, Key::M, Key::H, Key::PageUp, Key::PageDown}) any |= key_pressed(k);
  for (int digit = 0; digit <= 9; ++digit) any |= digit_pressed(digit);
  for (int n = 1; n <= 10; ++n) any |= function_key_pressed(n);
  return any;
}

}  // namespace shadowlab
