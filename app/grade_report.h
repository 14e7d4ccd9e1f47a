// The class's reports, merged from the per-lab records of `shadowlab grade` (students/<name>/lab_NN.json):
// results.json (schema "shadowlab-grade", version kGradeSchemaVersion; see the README), results.csv
// (one row per student x lab x criterion), junit.xml (one test suite per student, one case per lab), and
// gradescope/<name>/results.json (Gradescope's autograder format: tests with score, max_score, output).
// Also what every report writer shares: text that cannot break a report (report_text, report_json) and
// the output folder written without ever following a link (OutFolder).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/out_folder.h"

namespace shadowlab {

// Version 2: the status `missing` (a lab whose exercise files are not in the submission; version 1
// called that `failed`).
inline constexpr int kGradeSchemaVersion = 2;

// The statuses of a graded lab, in the order reports list them.
inline const std::vector<std::string> kGradeStatuses = {"passed",    "failed",  "missing",     "compile_error",
                                                        "timed_out", "crashed", "grader_error"};

// ---- Text from students, as every report carries it ----------------------------------------------

// `text` as valid UTF-8 that cannot rewrite a terminal or a report's lines: each byte that is not part
// of a valid UTF-8 sequence, and each control character but tab and newline (ESC, CR, DEL, the C1
// controls), is shown as \xNN ("caf\xe9" for a Latin-1 "cafe" with an accent). The one escaping every
// writer uses: JSON (report_json), CSV, JUnit, Gradescope, and `check --json`.
std::string report_text(std::string_view text);

// `value` as JSON text (indent 2, a final newline), every string and key through report_text: no
// name, message or file content can make it throw. (By value: pass a large one with std::move.)
std::string report_json(nlohmann::json value);

struct MergeSummary {
  int students = 0;
  int labs = 0;
  int passed = 0;
  int grader_errors = 0;
  int missing = 0;
  std::vector<std::string> written;  // the report files
};

// Reads every record under out/students; `expected` lists the students (names) that must be there.
// A lab a student's grading planned and never recorded, or every lab of `labs` for an expected student
// with no folder at all (or a link in its place: nothing is read through it), becomes a grader_error
// "no result": nothing is silently missing. Writes the reports atomically; throws when they cannot be
// written.
MergeSummary merge_grades(const OutFolder& out, const std::vector<std::string>& expected, const std::vector<int>& labs);

// The record of a lab that was not graded (no result, refused submission...): the same fields as a
// graded one, no criteria.
nlohmann::json lab_record(int lab, const std::string& student, const std::string& status, const std::string& message);

}  // namespace shadowlab
