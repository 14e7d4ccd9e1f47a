// app/imgui_gl.h compiled (never linked or run) against the stand-in tests/compat/imgui191: ImGui 1.91.9,
// where ImTextureID is ImU64 and the OpenGL3 backend still leaves the atlas texture to the application.
#include <type_traits>

#include "tests/compat/imgui_gl_calls.h"

static_assert(IMGUI_VERSION_NUM >= 19140 && IMGUI_VERSION_NUM < 19200,
              "the stand-in header must be found before the real imgui.h");
static_assert(std::is_same_v<ImTextureID, ImU64>);

// The calls themselves: tests/compat/imgui_gl_calls.h.
