#include "app/check_cmd.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "app/grade_report.h"
#include "app/command_options.h"
#include "grading/check.h"
#include "grading/platform_process.h"
#include "labs/registry.h"
#include "renderer/context.h"
#include "core/image_io.h"

namespace shadowlab {

namespace fs = std::filesystem;

std::vector<int> parse_lab_list(const std::string& text) {
  std::vector<int> numbers;
  std::string gradable;
  for (const auto& lab : all_labs())
    if (lab.check) gradable += (gradable.empty() ? "" : ", ") + std::to_string(lab.number);
  if (text == "all") {
    for (const auto& lab : all_labs())
      if (lab.check) numbers.push_back(lab.number);
    return numbers;
  }
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    int n = -1;
    try {
      std::size_t used = 0;
      n = std::stoi(item, &used);
      if (used != item.size()) n = -1;
    } catch (const std::exception&) {
    }
    const Lab* lab = n >= 0 ? find_lab(n) : nullptr;
    if (!lab || !lab->check)
      throw std::invalid_argument("--lab " + text + ": '" + item + "' is not a lab with a check; valid: all, " + gradable);
    numbers.push_back(n);
  }
  return numbers;
}

namespace {

// The lab's preset as `--set` assignments (none for an empty name; the name was checked before).
std::vector<std::string> preset_assignments(const Lab& lab, const std::string& name) {
  std::vector<std::string> sets;
  if (!name.empty())
    for (const auto& [key, value] : find_preset(lab, name).values) sets.push_back(key + "=" + value);
  return sets;
}

void print_result(const CheckResult& r) {
  std::printf("lab %d %-18s %-8s %s  (%.1f s)\n", r.lab, r.slug.c_str(), impl_name(r.impl),
              r.passed() ? "PASS" : r.status() == CheckStatus::Failed ? "FAIL" : status_name(r.status()), r.seconds);
  if (!r.error.empty()) std::printf("    %s: %s\n", !r.students_error                            ? "grader error"
                                         : r.status() == CheckStatus::CompileError ? "your file does not build"
                                                                                   : "your exercise failed", r.error.c_str());
  if (!r.warnings.empty()) std::printf("    warnings:\n%s", r.warnings.c_str());
  for (const auto& note : r.notes) std::printf("    note: %s\n", note.c_str());
  for (const auto& c : r.criteria) {
    const char* verdict = c.basis == Criterion::kNotMeasurable ? "n/a" : c.passed() ? "ok" : "FAIL";
    const char* basis = c.basis == Criterion::kSolutionValue  ? " [limit: the solution's own value on this scene]"
                        : c.basis == Criterion::kNotMeasurable ? " [not measurable on this scene: not graded]"
                                                               : "";
    std::printf("    %-4s %-40s %12.6g %s %-10.6g %s%s\n", verdict, c.metric.c_str(), c.value,
                c.direction == Criterion::kAtMost ? "<=" : ">=", c.limit, c.why.c_str(), basis);
    if (!c.passed()) std::printf("         %s\n", c.explain().c_str());
  }
}

}  // namespace

int run_check(const CheckOptions& options) {
  try {
    if (!options.submission.empty() && !platform::grading_unavailable().empty())
      throw std::runtime_error("--submission: " + platform::grading_unavailable());  // not a Linux build
    const std::vector<int> numbers = parse_lab_list(options.labs);
    if (numbers.empty()) throw std::runtime_error("no lab has a check yet");
    for (int number : numbers) {  // a bad --preset or --set is a usage error, found before anything renders
      ParamSet p = lab_params(*find_lab(number));
      try {
        apply_preset_option(p, *find_lab(number), options.preset);
      } catch (const std::invalid_argument& e) {
        if (numbers.size() == 1) throw;
        throw std::invalid_argument(e.what() + std::string(" (--preset applies to every lab --lab selects)"));
      }
      for (const auto& a : options.assignments) apply_set_option(p, a);
    }
    if (!options.submission.empty() && !fs::is_directory(options.submission))
      throw std::runtime_error("--submission " + options.submission + ": not a folder (give the folder holding labs/)");
    if (!options.submission.empty() && options.impl == "solution")
      throw std::runtime_error("--submission grades the submission's exercise files; --impl solution does not apply");
    const Impl impl = options.impl == "solution" ? Impl::Solution : Impl::Exercise;
    const Scene scene = load_scene_or_default(options.scene_file);
    if (!options.out_dir.empty()) make_output_dir(options.out_dir);
    // Find out now, not after every lab has been graded, if the JSON cannot be written.
    if (!options.json_file.empty()) {
      const fs::path folder = fs::path(options.json_file).parent_path();
      try {
        prove_writable_folder(folder.empty() ? "." : folder.string());
      } catch (const std::exception& e) {
        throw std::runtime_error("--json " + options.json_file + ": " + e.what());
      }
      if (fs::is_directory(options.json_file))
        throw std::runtime_error("--json " + options.json_file + ": is a folder; give a file name");
    }
    std::string error;
    auto context = HeadlessContext::create(&error);
    if (!context) {
      std::fprintf(stderr, "shadowlab check: grader error: %s\n", one_line_error(error).c_str());
      return 3;
    }

    bool all_passed = true, grader_error = false;
    nlohmann::json report = {{"labs", nlohmann::json::array()}};
    {
      std::unique_ptr<Renderer> made;
      try {
        made = std::make_unique<Renderer>();
      } catch (const std::exception& e) {
        std::fprintf(stderr, "shadowlab check: grader error: %s\n", one_line_error(e.what()).c_str());
        return 3;
      }
      Renderer& renderer = *made;
      for (int number : numbers) {
        CheckRun run;
        run.impl = impl;
        run.submission = options.submission;
        run.seed = options.seed;
        run.assignments = preset_assignments(*find_lab(number), options.preset);  // the preset first, --set over it
        run.assignments.insert(run.assignments.end(), options.assignments.begin(), options.assignments.end());
        run.out_dir = options.out_dir;
        run.foreign_scene = !options.scene_file.empty();
        const CheckResult result = run_lab_check(renderer, *find_lab(number), scene, run);
        print_result(result);
        std::fflush(stdout);
        all_passed = all_passed && result.passed();
        grader_error = grader_error || result.status() == CheckStatus::GraderError;
        report["labs"].push_back(result.to_json());
        // Written after every lab, so a run that is killed keeps what it graded; through report_json, so
        // that a byte of a student's file quoted in a compile error cannot stop it (\xNN).
        if (!options.json_file.empty()) write_text_atomic(options.json_file, report_json(report));
      }
    }
    std::printf("%s\n", all_passed ? "all checks passed" : grader_error ? "grader error (see above)" : "some checks failed");
    return grader_error ? 3 : all_passed ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab check: %s\n", one_line_error(e.what()).c_str());
    return 2;
  }
}

}  // namespace shadowlab
