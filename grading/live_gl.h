// The labs' GL exercises live in the window: the student's file built into a shared library and loaded
// into the window's process (the course's own practice: the student's GL calls draw the window's maps).
#pragma once

#include <filesystem>
#include <string>

#include "renderer/gl_host_code.h"

namespace shadowlab {

// Whether the window runs this GL exercise file live: labs 0, 3, 5 and 9's gl_*.cpp.
bool live_gl_exercise_supported(const std::string& file);

// Builds `text` (the student's `file`, e.g. "labs/00_basic_shadow_map/gl_shadow_target.cpp") in the
// empty folder `dir` with the exercises' compiler and flags into a shared library, loads it for good and
// returns `code` with the functions it defines in place of the renderer's. Throws with the compiler's
// words (file:line:col) when it does not build, or the loader's when it cannot be loaded. Linux only
// (platform::load_library_symbol).
GlHostCode build_live_gl_exercise(const std::filesystem::path& dir, const std::string& file, const std::string& text,
                                  GlHostCode code = {});

}  // namespace shadowlab
