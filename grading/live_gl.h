// Lab 0's GL exercise live in the window: its file built into a shared library and loaded into the
// window's process (the course's own practice: the student's GL calls draw the window's shadow map).
#pragma once

#include <filesystem>
#include <string>

#include "renderer/shadow_target.h"

namespace shadowlab {

// Builds `text` (the student's `file`, e.g. "labs/00_basic_shadow_map/gl_shadow_target.cpp") in the
// empty folder `dir` with the exercises' compiler and flags into a shared library, loads it for good and
// returns its two functions. Throws with the compiler's words (file:line:col) when it does not build, or
// the loader's when it cannot be loaded. Linux only (platform::load_library_symbol).
// Whether the window runs this GL exercise file live: lab 0's gl_shadow_target.cpp. Labs 3, 5 and 9's
// are graded by Check from the file on disk, but the window draws with the renderer's own functions.
bool live_gl_exercise_supported(const std::string& file);

ShadowTargetCode build_live_gl_exercise(const std::filesystem::path& dir, const std::string& file,
                                        const std::string& text);

}  // namespace shadowlab
