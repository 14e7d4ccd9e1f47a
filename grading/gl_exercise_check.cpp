#include "grading/gl_exercise_check.h"

#include <filesystem>

#include "renderer/shader.h"  // data_dir

namespace shadowlab {

namespace fs = std::filesystem;

std::unique_ptr<CppExercise> start_gl_exercise(const CheckContext& ctx, CheckResult& result, const GlExerciseSlot& slot) {
  const bool solution = ctx.impl == Impl::Solution && ctx.submission.empty();
  const fs::path file = !ctx.submission.empty() ? fs::absolute(ctx.submission / slot.exercise)
                                                : data_dir() / (solution ? slot.solution : slot.exercise);
  if (!ctx.submission.empty() && !fs::is_regular_file(file)) {
    result.criteria.push_back({slot.prefix + ".file_submitted", 0.0, Criterion::kAtLeast, 1.0, slot.exercise + " in the submission",
                               "hand in " + slot.exercise + " too: " + slot.part + "."});
    return nullptr;
  }
  // The lab folder's exercise host (labs/CMakeLists.txt): the folder's name.
  const std::string host = fs::path(slot.exercise).parent_path().filename().string();
  if (const std::string why = cpp_exercise_unavailable(host); !why.empty()) {
    result.notes.push_back(slot.exercise + " is not graded here: " + why);
    return nullptr;
  }
  CppExerciseSpec spec;
  spec.source = file;
  spec.display_name = solution ? slot.solution : slot.exercise;
  spec.host = host;
  spec.headers = slot.headers;
  spec.renders = true;
  return std::make_unique<CppExercise>(spec);
}

}  // namespace shadowlab
