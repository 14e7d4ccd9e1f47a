// The class's reports, merged from the per-lab records of `shadowlab grade` (students/<name>/lab_NN.json):
// results.json (schema "shadowlab-grade", version kGradeSchemaVersion; see the README), results.csv
// (one row per student x lab x criterion), junit.xml (one test suite per student, one case per lab), and
// gradescope/<name>/results.json (Gradescope's autograder format: tests with score, max_score, output).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace shadowlab {

inline constexpr int kGradeSchemaVersion = 1;

// The statuses of a graded lab, in the order reports list them.
inline const std::vector<std::string> kGradeStatuses = {"passed",   "failed",  "compile_error",
                                                        "timed_out", "crashed", "grader_error"};

struct MergeSummary {
  int students = 0;
  int labs = 0;
  int passed = 0;
  int grader_errors = 0;
  std::vector<std::string> written;  // the report files
};

// Reads every record under out_dir/students; `expected` lists the students (names) that must be there.
// A lab a student's grading planned and never recorded, or every lab of `labs` for an expected student
// with no folder at all, becomes a grader_error "no result": nothing is silently missing. Writes the
// reports atomically; throws when they cannot be written.
MergeSummary merge_grades(const std::filesystem::path& out_dir, const std::vector<std::string>& expected,
                          const std::vector<int>& labs);

// The record of a lab that was not graded (no result, refused submission...): the same fields as a
// graded one, no criteria.
nlohmann::json lab_record(int lab, const std::string& student, const std::string& status, const std::string& message);

}  // namespace shadowlab
