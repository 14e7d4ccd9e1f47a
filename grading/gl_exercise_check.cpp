#include "grading/gl_exercise_check.h"

#include <filesystem>

#include "renderer/shader.h"  // data_dir

namespace shadowlab {

std::unique_ptr<CppExercise> build_gl_exercise(const CheckContext& ctx, CheckResult& result, const GlExerciseFiles& files) {
  namespace fs = std::filesystem;
  const bool solution = ctx.impl == Impl::Solution && ctx.submission.empty();
  const fs::path file = !ctx.submission.empty() ? fs::absolute(ctx.submission / files.exercise)
                                                : data_dir() / (solution ? files.solution : files.exercise);
  if (!ctx.submission.empty() && !fs::is_regular_file(file)) {
    result.criteria.push_back({"gl_setup.file_submitted", 0.0, Criterion::kAtLeast, 1.0, files.exercise + " in the submission",
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

}  // namespace shadowlab
