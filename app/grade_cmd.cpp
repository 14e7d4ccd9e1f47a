#include "app/grade_cmd.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/check_cmd.h"
#include "app/exit_codes.h"
#include "app/grade_report.h"
#include "app/headless.h"
#include "app/submission.h"
#include "labs/lab.h"
#include "labs/platform_process.h"
#include "renderer/image_io.h"

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kExitAllPassed = kExitOk, kExitSomeFailed = kExitCheckFailed, kExitGraderError = kExitRuntime;

struct Run {
  GradeOptions options;
  fs::path out;
  std::vector<int> labs;
  fs::path self;  // this executable: each lab runs `self check ...`
};

std::string lab_stem(int lab) {
  char text[16];
  std::snprintf(text, sizeof text, "lab_%02d", lab);
  return text;
}

json read_json(const fs::path& path) {
  std::ifstream in(path);
  return json::parse(in, nullptr, /*allow_exceptions=*/false);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string last_line(const std::string& text) {
  std::string t = text;
  while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
  const auto nl = t.rfind('\n');
  return nl == std::string::npos ? t : t.substr(nl + 1);
}

// FNV-1a: what a lab's result depends on (the grader binary, the limits, the student's files), so a
// rerun skips only results that would come out the same.
struct Fingerprint {
  std::uint64_t h = 1469598103934665603ull;
  void add(const std::string& s) {
    for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    h = (h ^ 0xff) * 1099511628211ull;
  }
  std::string hex() const {
    char text[20];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
  }
};

std::string input_fingerprint(const Run& run, const Lab& lab, const fs::path& root) {
  Fingerprint f;
  std::error_code ec;
  f.add(std::to_string(fs::file_size(run.self, ec)));
  f.add(std::to_string(fs::last_write_time(run.self, ec).time_since_epoch().count()));
  f.add(std::to_string(run.options.cpu_time) + "/" + std::to_string(run.options.timeout) + "/" +
        std::to_string(run.options.memory_mb) + "/" + run.options.images);
  f.add(std::to_string(lab.number));
  for (const auto& file : lab.exercise_files) f.add(file + "\n" + read_text(root / file));
  return f.hex();
}

// The criteria of the check's JSON for one lab, as the reports give them:
// [{metric, value, op ("<=" or ">="), limit, passed, sentence, why}] (sentence: the fact, and what to
// change when it failed).
json criteria_of(const json& lab) {
  json out = json::array();
  for (const auto& c : lab.value("criteria", json::array())) {
    const bool at_most = c.contains("max");
    out.push_back({{"metric", c.value("metric", "")}, {"value", c.value("value", json())},
                   {"op", at_most ? "<=" : ">="}, {"limit", at_most ? c["max"] : c.value("min", json())},
                   {"passed", c.value("passed", false)}, {"sentence", c.value("sentence", "")},
                   {"why", c.value("why", "")}});
  }
  return out;
}

std::string failed_criteria_text(const json& criteria) {
  int failed = 0;
  std::string first;
  for (const auto& c : criteria) {
    if (c.value("passed", false)) continue;
    if (++failed == 1) first = c.value("sentence", c.value("metric", ""));
  }
  return std::to_string(failed) + " of " + std::to_string(criteria.size()) + " criteria failed; first: " + first;
}

// The status and message of one lab from how its check process ended and what it wrote.
void classify(const Run& run, const platform::ChildOutcome& o, const fs::path& check_json, const fs::path& log,
              json& record) {
  using Kind = platform::ChildOutcome::Kind;
  const std::string log_tail = last_line(read_text(log));
  auto set = [&](const std::string& status, const std::string& message) {
    record["status"] = status;
    record["message"] = message;
  };
  if (o.kind == Kind::NotStarted) return set("grader_error", "the check could not start: " + o.error);
  if (o.kind == Kind::TimedOut)
    return set("timed_out", "no result within " + std::to_string(static_cast<int>(run.options.timeout)) +
                                " s (wall clock): the check was stopped");
  if (o.kind == Kind::Signalled && (o.signal == SIGXCPU || (o.signal == SIGKILL && o.cpu_seconds >= run.options.cpu_time)))
    return set("timed_out", "no result after " + std::to_string(static_cast<int>(run.options.cpu_time)) +
                                " s of CPU time: the check was stopped (an endless loop, or an exercise far slower "
                                "than the solution)");
  const bool out_of_memory = log_tail.find("bad_alloc") != std::string::npos ||
                             log_tail.find("Cannot allocate memory") != std::string::npos;
  const std::string memory_note =
      out_of_memory ? " (over the memory limit of " + std::to_string(run.options.memory_mb) + " MB)" : "";
  if (o.kind == Kind::Signalled) return set("crashed", "the check process died: " + o.signal_name + memory_note);
  const json report = read_json(check_json);
  const json lab = report.is_object() && report.contains("labs") && !report["labs"].empty() ? report["labs"][0] : json();
  if (o.exit_code == 2 || o.exit_code == 3 || (o.exit_code <= 1 && !lab.is_object()))
    return set("grader_error", "the check ended with exit code " + std::to_string(o.exit_code) +
                                   (lab.is_object() ? "" : " and no result") + ": " + log_tail);
  if (o.exit_code > 3) return set("crashed", "the check exited with code " + std::to_string(o.exit_code) + " and no result");
  record["criteria"] = criteria_of(lab);
  const std::string error = lab.value("error", "");
  std::string status = lab.value("status", "");
  if (status.empty()) status = lab.value("passed", false) ? "passed" : error.empty() ? "failed" : "compile_error";
  if (o.exit_code == 0 && status != "passed") status = "grader_error";  // exit 0 must mean passed
  if (status == "grader_error" && error.find("bad_alloc") != std::string::npos) {
    status = "crashed";
    return set(status, "out of memory (limit " + std::to_string(run.options.memory_mb) + " MB): " + error);
  }
  if (status == "passed") return set(status, "all " + std::to_string(record["criteria"].size()) + " criteria passed");
  if (!error.empty()) return set(status, error);
  set(status, failed_criteria_text(record["criteria"]));
}

// Keeps the diff images the --images choice asks for, with paths relative to the output folder.
json kept_images(const Run& run, const fs::path& folder, const std::string& status) {
  json images = json::array();
  const bool keep = run.options.images == "all" || (run.options.images == "failed" && status != "passed");
  std::error_code ec;
  if (!keep) {
    fs::remove_all(folder, ec);
    return images;
  }
  if (!fs::is_directory(folder)) return images;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    const bool diff = name.size() > 9 && name.compare(name.size() - 9, 9, "_diff.png") == 0;
    if (!diff && run.options.images != "all") {
      fs::remove(f, ec);
      continue;
    }
    images.push_back(fs::relative(f, run.out, ec).generic_string());
  }
  return images;
}

// A file the lab needs, as the submission has it: a missing file, a link, or a path that leads out of
// the submission (a linked folder) is the student's problem.
std::string missing_or_linked(const Lab& lab, const fs::path& root) {
  std::string problem;
  std::error_code ec;
  const std::string inside = (fs::weakly_canonical(root, ec) / "").string();
  for (const auto& file : lab.exercise_files) {
    const fs::path p = root / file;
    std::string why;
    if (fs::is_symlink(p)) why = "a link; submit the file itself";
    else if (!fs::is_regular_file(p)) why = "not in the submission";
    else if (fs::weakly_canonical(p, ec).string().rfind(inside, 0) != 0) why = "leads out of the submission (a linked folder)";
    if (!why.empty()) problem += (problem.empty() ? "" : "; ") + file + ": " + why;
  }
  return problem;
}

void print_lab(const std::string& student, const json& r, bool recorded) {
  std::printf("%-20s lab %d %-18s %-13s %6.1f s %6.0f MB%s\n", student.c_str(), r.value("lab", -1),
              r.value("slug", "").c_str(), r.value("status", "").c_str(), r.value("seconds", 0.0),
              r.value("peak_memory_mb", 0.0), recorded ? "  (recorded before)" : "");
  std::fflush(stdout);
}

// Grades one lab of one submission in its own process and records the result at once.
json grade_lab(const Run& run, const Lab& lab, const std::string& student, const fs::path& root, const fs::path& dir) {
  const fs::path record_path = dir / (lab_stem(lab.number) + ".json");
  const std::string input = input_fingerprint(run, lab, root);
  if (!run.options.again) {
    const json old = read_json(record_path);
    if (old.is_object() && old.value("input", "") == input && old.value("status", "") != "grader_error") {
      print_lab(student, old, true);
      return old;
    }
  }
  json record = lab_record(lab.number, student, "grader_error", "");
  record["input"] = input;
  record["limits"] = {{"cpu_time_s", run.options.cpu_time}, {"timeout_s", run.options.timeout},
                      {"memory_mb", run.options.memory_mb}};
  if (const std::string problem = missing_or_linked(lab, root); !problem.empty()) {
    record["status"] = "failed";
    record["message"] = problem;
  } else {
    const fs::path check_json = dir / (lab_stem(lab.number) + ".check.json");
    const fs::path log = dir / (lab_stem(lab.number) + ".log");
    const fs::path images = dir / lab_stem(lab.number);
    // The check's temporary files (lab 2's compiled exercise) go to a folder of the student's own, emptied
    // before and after: a check killed at a limit, or a grading run killed outright, leaves nothing in /tmp,
    // and the next run starts clean.
    const fs::path scratch = dir / (lab_stem(lab.number) + ".tmp");
    std::error_code ec;
    fs::remove(check_json, ec);
    fs::remove_all(images, ec);
    fs::remove_all(scratch, ec);
    fs::create_directories(scratch, ec);
    const std::vector<std::string> argv = {run.self.string(), "check", "--lab", std::to_string(lab.number),
                                           "--impl", "exercise", "--submission", root.string(),
                                           "--json", check_json.string(), "--out", images.string()};
    const platform::ChildLimits limits{run.options.timeout, static_cast<std::uint64_t>(run.options.memory_mb) << 20,
                                       run.options.cpu_time};
    const platform::ChildOutcome o = platform::run_child(argv, limits, log, {{"TMPDIR", scratch.string()}});
    fs::remove_all(scratch, ec);
    classify(run, o, check_json, log, record);
    record["seconds"] = o.seconds;
    record["cpu_seconds"] = o.cpu_seconds;
    record["peak_memory_mb"] = o.peak_rss_mb;
    if (o.kind == platform::ChildOutcome::Kind::Exited) record["exit"] = {{"code", o.exit_code}};
    if (o.kind == platform::ChildOutcome::Kind::Signalled) record["exit"] = {{"signal", o.signal_name}};
    record["log"] = fs::relative(log, run.out, ec).generic_string();
    record["images"] = kept_images(run, images, record["status"]);
  }
  write_text_atomic(record_path, record.dump(2) + "\n");
  print_lab(student, record, false);
  return record;
}

// Grades every lab of one submission; returns the exit code it alone would give.
int grade_submission(const Run& run, const std::string& path) {
  const std::string name = submission_name(path);
  const fs::path dir = run.out / "students" / name;
  // The student's folder is this run's alone (the tasks of a parallel or Slurm run share --out).
  make_output_dir(dir.string());
  std::error_code ec;
  json submission = {{"name", name}, {"source", fs::absolute(path, ec).string()}, {"labs", run.labs}};
  fs::path unpacked;
  fs::path root;
  try {
    if (is_archive_name(path) && fs::is_regular_file(path)) {
      submission["kind"] = "archive";
      // Unpacked into the student's own output folder (this task's alone), not /tmp: a run killed while
      // grading leaves it there, and the next run over the same --out removes it before unpacking again.
      unpacked = dir / "unpacked";
      fs::remove_all(unpacked, ec);
      fs::create_directories(unpacked);
      fs::permissions(unpacked, fs::perms::owner_all, ec);
      unpack_archive(path, unpacked);
      root = find_project_root(unpacked);
    } else {
      submission["kind"] = "folder";
      if (!fs::is_directory(path)) throw SubmissionError(path + ": neither a folder nor a .zip/.tar archive");
      root = find_project_root(path);
    }
  } catch (const SubmissionError& e) {
    submission["error"] = e.what();
  }
  write_text_atomic(dir / "submission.json", submission.dump(2) + "\n");
  int code = kExitAllPassed;
  for (int n : run.labs) {
    const Lab& lab = *find_lab(n);
    json record;
    if (submission.contains("error")) {
      record = lab_record(n, name, "failed", "submission refused: " + submission["error"].get<std::string>());
      write_text_atomic(dir / (lab_stem(n) + ".json"), record.dump(2) + "\n");
      print_lab(name, record, false);
    } else {
      record = grade_lab(run, lab, name, root, dir);
    }
    const std::string status = record.value("status", "");
    if (status == "grader_error") code = kExitGraderError;
    else if (status != "passed" && code == kExitAllPassed) code = kExitSomeFailed;
  }
  if (!unpacked.empty()) fs::remove_all(unpacked, ec);
  return code;
}

// Several submissions at once: GNU parallel runs `shadowlab grade ONE --no-merge` per submission, each
// job's software rasteriser on one thread (LP_NUM_THREADS=1) so that jobs do not fight for cores.
int grade_with_parallel(const Run& run) {
  const fs::path list = run.out / ".submissions.list";
  std::string text;
  std::error_code ec;
  for (const auto& s : run.options.submissions) text += fs::absolute(s, ec).string() + '\0';
  write_text_atomic(list, text);
  const double per_submission = static_cast<double>(run.labs.size()) * (run.options.timeout + 10.0) + 120.0;
  std::vector<std::string> argv = {"parallel", "--will-cite", "--quote", "--line-buffer", "--halt", "never",
                                   "--jobs", std::to_string(run.options.jobs), "--timeout",
                                   std::to_string(static_cast<int>(per_submission)), "--joblog",
                                   (run.out / "parallel.joblog").string(), "-0", "--arg-file", list.string(),
                                   run.self.string(), "grade", "--no-merge", "--out", run.out.string(), "--lab",
                                   run.options.labs, "--cpu-time", std::to_string(run.options.cpu_time),
                                   "--timeout", std::to_string(run.options.timeout), "--memory",
                                   std::to_string(run.options.memory_mb), "--images", run.options.images};
  if (run.options.again) argv.push_back("--again");
  argv.push_back("{}");
  std::map<std::string, std::string> env;
  if (!std::getenv("LP_NUM_THREADS")) env["LP_NUM_THREADS"] = "1";
  const platform::ChildOutcome o = platform::run_child(argv, {}, "", env);
  fs::remove(list, ec);
  if (o.kind == platform::ChildOutcome::Kind::NotStarted)
    throw std::runtime_error("GNU parallel is needed for --jobs " + std::to_string(run.options.jobs) + ": " + o.error +
                             " (scripts/setup installs it; or use --jobs 1)");
  return o.kind == platform::ChildOutcome::Kind::Exited && o.exit_code == 0 ? kExitAllPassed : kExitSomeFailed;
}

Run plan_run(const GradeOptions& options) {
  Run run;
  run.options = options;
  if (options.out_dir.empty()) throw std::invalid_argument("--out is required");
  if (options.submissions.empty() && !options.merge_only)
    throw std::invalid_argument("no submission given: shadowlab grade SUBMISSION... --out DIR");
  if (options.jobs < 1) throw std::invalid_argument("--jobs must be 1 or more");
  if (!(options.timeout > 0)) throw std::invalid_argument("--timeout must be a positive number of seconds");
  if (!(options.cpu_time > 0)) throw std::invalid_argument("--cpu-time must be a positive number of seconds");
  if (options.memory_mb < 256) throw std::invalid_argument("--memory must be at least 256 (MB)");
  if (options.images != "none" && options.images != "failed" && options.images != "all")
    throw std::invalid_argument("--images " + options.images + ": valid: none, failed, all");
  run.labs = parse_lab_list(options.labs);
  std::map<std::string, std::string> names;
  for (const auto& s : options.submissions) {
    if (!fs::exists(s)) throw std::invalid_argument(s + ": no such submission (a folder or a .zip/.tar archive)");
    const auto [it, fresh] = names.emplace(submission_name(s), s);
    if (!fresh)
      throw std::invalid_argument("two submissions would be reported as '" + it->first + "': " + it->second + " and " + s);
  }
  // The whole --out is locked by the run that merges; its parallel or Slurm tasks (--no-merge) each
  // lock only their student's folder.
  if (options.no_merge) prove_writable_folder(options.out_dir);
  else make_output_dir(options.out_dir);
  run.out = fs::absolute(options.out_dir);
  run.self = platform::self_executable();
  return run;
}

}  // namespace

int run_grade(const GradeOptions& options) {
  // A task of a parallel or Slurm run: it goes when whoever started it goes, and takes its checks along.
  if (options.no_merge) platform::die_with_parent();
  Run run;
  try {
    run = plan_run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab grade: %s\n", e.what());
    return kExitUsage;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    int code = kExitAllPassed;
    if (!options.merge_only) {
      if (options.jobs > 1 && options.submissions.size() > 1) {
        code = grade_with_parallel(run);
      } else {
        for (const auto& s : options.submissions) code = std::max(code, grade_submission(run, s));
      }
    }
    if (options.no_merge) return code;
    std::vector<std::string> names;
    for (const auto& s : options.submissions) names.push_back(submission_name(s));
    const MergeSummary m = merge_grades(run.out, names, run.labs);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%d submissions: %d of %d labs passed, %d grader errors (%.0f s)\n", m.students,
                m.passed, m.labs, m.grader_errors, seconds);
    for (const auto& f : m.written) std::printf("wrote %s\n", f.c_str());
    if (m.grader_errors > 0) return kExitGraderError;
    return m.passed == m.labs ? kExitAllPassed : kExitSomeFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab grade: %s\n", one_line_error(e.what()).c_str());
    return kExitGraderError;
  }
}

}  // namespace shadowlab
