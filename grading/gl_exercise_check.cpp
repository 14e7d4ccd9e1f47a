#include "grading/gl_exercise_check.h"

#include <cstdlib>
#include <filesystem>

#include "renderer/shader.h"  // data_dir

namespace shadowlab {

std::unique_ptr<CppExercise> build_gl_exercise(const CheckContext& ctx, CheckResult& result, const GlExerciseFiles& files) {
  namespace fs = std::filesystem;
  const bool solution = ctx.impl == Impl::Solution && ctx.submission.empty();
  const fs::path file = !ctx.submission.empty() ? fs::absolute(ctx.submission / files.exercise)
                                                : data_dir() / (solution ? files.solution : files.exercise);
  if (!ctx.submission.empty() && !fs::is_regular_file(file)) {
    result.criteria.push_back({files.prefix + ".file_submitted", 0.0, Criterion::kAtLeast, 1.0, files.exercise + " in the submission",
                               "hand in " + files.exercise + " too: " + files.part + "."});
    return nullptr;
  }
  if (const std::string why = cpp_exercise_unavailable(files.host); !why.empty()) {
    result.notes.push_back(files.exercise + " is not graded here: " + why);
    return nullptr;
  }
  CppExerciseSpec spec;
  spec.source = file;
  spec.display_name = solution ? files.solution : files.exercise;
  spec.host = files.host;
  spec.headers = files.headers;
  spec.renders = true;
  return std::make_unique<CppExercise>(spec);
}

void add_pass_binding_criteria(const GlPassState& s, std::vector<Criterion>& c) {
  const double bound = s.pass_framebuffer == s.framebuffer && s.framebuffer != 0 ? 0.0 : 1.0;
  c.push_back({"gl_setup.pass_not_into_the_map", bound, Criterion::kAtMost, 0.0,
               "GL_DRAW_FRAMEBUFFER_BINDING after " + s.begin + " is target.framebuffer",
               s.begin + " must bind target.framebuffer (glBindFramebuffer(GL_FRAMEBUFFER, ...)): otherwise the " + s.pass +
                   " draws into the window."});
  const double viewport = std::abs(s.viewport[0]) + std::abs(s.viewport[1]) + std::abs(s.viewport[2] - s.size) +
                          std::abs(s.viewport[3] - s.size);
  const std::string size = std::to_string(s.size);
  c.push_back({"gl_setup.viewport_error", viewport, Criterion::kAtMost, 0.0,
               "pixels between GL_VIEWPORT after " + s.begin + " and (0, 0, " + size + ", " + size + "); it was the window's " +
                   std::to_string(s.window_width) + " x " + std::to_string(s.window_height),
               "glViewport(0, 0, target.size, target.size) in " + s.begin + ": the viewport is not part of the "
               "framebuffer, and the window's leaves most of the scene outside the map (or the map's corner only)."});
}

Criterion gl_errors_criterion(const GlPassState& s) {
  const double errors = (s.error_after_create != 0) + (s.error_after_begin != 0);  // GL_NO_ERROR is 0
  return {"gl_setup.gl_errors", errors, Criterion::kAtMost, 0.0, "glGetError after " + s.create + " and after " + s.begin,
          "a call failed (see gl_error_after_create and _begin in the metrics): check each call's arguments against the "
          "OpenGL 3.3 reference."};
}

}  // namespace shadowlab
