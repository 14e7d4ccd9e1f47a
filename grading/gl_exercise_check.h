// The grader's half of a lab's GL exercise (labs 0, 3 and 9: the student's OpenGL calls in a gl_*.cpp file,
// grading/cpp_exercise.h with `renders`): which file is graded and building it with the lab's host in the
// sandbox. The lab's check then calls the program and turns the state it answers into criteria.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "grading/check.h"
#include "grading/cpp_exercise.h"

namespace shadowlab {

struct GlExerciseFiles {
  std::string exercise;              // the student's file: "labs/03_vsm_setup/gl_moments_target.cpp"
  std::string solution;              // the renderer's own file, the solution: "renderer/moments_target.cpp"
  std::string host;                  // the lab folder's exercise host (labs/CMakeLists.txt): its name
  std::vector<std::string> headers;  // the includes the file may use
  std::string part;                  // as the advice names it: "lab 3's OpenGL part"
  std::string prefix = "gl_setup";   // the criteria's first name ("gl_stencil" for lab 9's)
};

// The graded file (a submission's, else the solution's or the exercise on disk) built with its host;
// nullptr after adding the failed criterion <prefix>.file_submitted (a submission without the file) or a
// note (no sandbox or no EGL here). Throws ExerciseError as CppExercise does.
std::unique_ptr<CppExercise> build_gl_exercise(const CheckContext& ctx, CheckResult& result, const GlExerciseFiles& files);

// What the start of every exercise's pass is graded on alike, read back by its host after the student's
// `begin` function ran with the window's framebuffer bound and a window-sized viewport.
struct GlPassState {
  std::string create, begin, pass;  // the functions' names and the pass's: "create_shadow_target", ..., "depth pass"
  int framebuffer = 0, pass_framebuffer = 0;  // target.framebuffer, GL_DRAW_FRAMEBUFFER_BINDING after `begin`
  const int* viewport = nullptr;              // GL_VIEWPORT after `begin`
  int size = 0, window_width = 0, window_height = 0;  // the map's size asked for, the window's viewport before
  int error_after_create = 0, error_after_begin = 0;  // glGetError after each function
};
// gl_setup.pass_not_into_the_map and gl_setup.viewport_error, exact.
void add_pass_binding_criteria(const GlPassState& s, std::vector<Criterion>& criteria);
// gl_setup.gl_errors: the functions that left a GL error, none allowed.
Criterion gl_errors_criterion(const GlPassState& s);

}  // namespace shadowlab
