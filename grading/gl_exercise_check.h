// The start of a lab's GL exercise check (lab 0's depth framebuffer, lab 9's stencil passes): which file
// is graded (a submission's, the solution when --impl solution, or the file on disk) and its program,
// built with the lab folder's exercise host and started in the sandbox with its own OpenGL context.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "grading/check.h"
#include "grading/cpp_exercise.h"

namespace shadowlab {

struct GlExerciseSlot {
  std::string exercise;              // "labs/00_basic_shadow_map/gl_shadow_target.cpp"; its folder names the host
  std::string solution;              // "renderer/shadow_target.cpp": the renderer's own file
  std::string prefix;                // the criteria's first name ("gl_setup")
  std::string part;                  // what the student is told to hand in ("lab 0's OpenGL part")
  std::vector<std::string> headers;  // the headers the file may include
};

// The program, or nullptr where the file is not graded: a submission without it (a failed
// `<prefix>.file_submitted` criterion) or no sandbox or host here (a note says why).
std::unique_ptr<CppExercise> start_gl_exercise(const CheckContext& ctx, CheckResult& result, const GlExerciseSlot& slot);

}  // namespace shadowlab
