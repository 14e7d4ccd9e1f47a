#include "app/check_cmd.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/headless.h"
#include "labs/check.h"
#include "labs/cpp_exercise.h"
#include "renderer/context.h"
#include "renderer/image_io.h"

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

void print_result(const CheckResult& r) {
  std::printf("lab %d %-18s %-8s %s  (%.1f s)\n", r.lab, r.slug.c_str(), impl_name(r.impl), r.passed() ? "PASS" : "FAIL",
              r.seconds);
  if (!r.error.empty()) std::printf("    error: %s\n", r.error.c_str());
  for (const auto& c : r.criteria) {
    std::printf("    %-4s %-34s %12.6g %s %-10.6g %s\n", c.passed() ? "ok" : "FAIL", c.metric.c_str(), c.value,
                c.direction == Criterion::kAtMost ? "<=" : ">=", c.limit, c.why.c_str());
  }
}

}  // namespace

int run_check(const CheckOptions& options) {
  try {
    const std::vector<int> numbers = parse_lab_list(options.labs);
    if (numbers.empty()) throw std::runtime_error("no lab has a check yet");
    for (int number : numbers) {  // a bad --set is a usage error, found before anything renders
      ParamSet p = lab_params(*find_lab(number));
      for (const auto& a : options.assignments) p.apply_assignment(a);
    }
    const Impl impl = options.impl == "exercise" ? Impl::Exercise : Impl::Solution;
    const Scene scene = load_scene_or_default(options.scene_file);
    if (!options.out_dir.empty()) make_output_dir(options.out_dir);
    // The JSON is written last; find out now, not after every lab has been graded, if it cannot be.
    if (!options.json_file.empty()) {
      const fs::path folder = fs::path(options.json_file).parent_path();
      try {
        make_output_dir(folder.empty() ? "." : folder.string());
      } catch (const std::exception& e) {
        throw std::runtime_error("--json " + options.json_file + ": " + e.what());
      }
      if (fs::is_directory(options.json_file))
        throw std::runtime_error("--json " + options.json_file + ": is a folder; give a file name");
    }
    std::string error;
    auto context = HeadlessContext::create(&error);
    if (!context) throw std::runtime_error(error);

    bool all_passed = true;
    nlohmann::json report = {{"labs", nlohmann::json::array()}};
    {
      Renderer renderer;
      for (int number : numbers) {
        const Lab& lab = *find_lab(number);
        CheckResult result;
        result.lab = lab.number;
        result.slug = lab.slug;
        result.impl = impl;
        const auto start = std::chrono::steady_clock::now();
        std::string exercise_status;  // a submitted C++ exercise that did not build, crashed or hung
        try {
          CheckContext ctx(renderer, lab, impl, scene, options.out_dir);
          ctx.assignments = options.assignments;
          ctx.submission = options.submission;
          result.parameters = ctx.params().to_json();
          lab.check(ctx, result);
          result.images = ctx.images;
        } catch (const ExerciseError& e) {
          result.error = e.what();
          exercise_status = e.status();
        } catch (const std::exception& e) {
          result.error = e.what();
        }
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        print_result(result);
        all_passed = all_passed && result.passed();
        report["labs"].push_back(result.to_json());
        if (!exercise_status.empty()) report["labs"].back()["status"] = exercise_status;
      }
    }
    if (!options.json_file.empty()) write_text_atomic(options.json_file, report.dump(2) + "\n");
    std::printf("%s\n", all_passed ? "all checks passed" : "some checks failed");
    return all_passed ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab check: %s\n", one_line_error(e.what()).c_str());
    return 2;
  }
}

}  // namespace shadowlab
