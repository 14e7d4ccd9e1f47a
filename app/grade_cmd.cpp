#include "app/grade_cmd.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <set>


#include <nlohmann/json.hpp>

#include "app/check_cmd.h"
#include "app/exit_codes.h"
#include "app/grade_report.h"
#include "app/command_options.h"
#include "grading/submission.h"
#include "grading/lab.h"
#include "grading/platform_process.h"
#include "labs/registry.h"
#include "core/platform.h"

// Sanitizer builds reserve terabytes of address space (ASan's shadow memory): no RLIMIT_AS there.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SHADOWLAB_GRADE_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SHADOWLAB_GRADE_SANITIZED 1
#endif
#endif

namespace shadowlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kExitAllPassed = kExitOk, kExitSomeFailed = kExitCheckFailed, kExitGraderError = kExitRuntime;

// The grader's own address space (a soft RLIMIT_AS on the `grade` process). Measured here: grading one
// student's every lab peaks at 97 MB, merging a class of 300 at all 17 labs at 330 MB (about 1 MB a
// student: 4 GB leaves room for some 3,500). A bug, or an input past the guards, then fails with
// bad_alloc in one lab's grading (a grader_error) instead of taking the machine. Only the soft limit: a
// check's process raises its own to --memory.
constexpr std::uint64_t kGraderAddressSpace = 4ull << 30;
constexpr std::uint64_t kMaxCheckJsonBytes = 16ull << 20;  // a check's JSON: a few KB
constexpr std::uint64_t kLogTailBytes = 64 << 10;          // the end of a check's log, for its last line

struct Run {
  GradeOptions options;
  OutFolder out;  // --out, opened once
  std::vector<int> labs;
  fs::path self;  // this executable: each lab runs `self check ...`
};

std::string lab_stem(int lab) {
  char text[16];
  std::snprintf(text, sizeof text, "lab_%02d", lab);
  return text;
}

json read_json(const OutFolder& dir, const std::string& name, std::uint64_t max_bytes) {
  const std::optional<std::string> text = dir.read(name, max_bytes);
  return text ? json::parse(*text, nullptr, /*allow_exceptions=*/false) : json();
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
  // Read only after exercise_file_problems found each a regular file within the limit.
  for (const auto& file : lab.exercise_files)
    f.add(file + "\n" + platform::read_regular_file(root / file, UnpackLimits{}.max_file_bytes));
  // A GL exercise (lab 0's gl_shadow_target.cpp) may be missing (its criterion fails) or refused by the
  // build (a link); a plain file within the limit counts, anything else counts as absent.
  for (const auto& file : lab.gl_exercise_files) {
    const fs::file_status st = fs::symlink_status(root / file, ec);
    const bool plain = fs::is_regular_file(st) && fs::file_size(root / file, ec) <= UnpackLimits{}.max_file_bytes;
    f.add(file + (plain ? "\n" + platform::read_regular_file(root / file, UnpackLimits{}.max_file_bytes) : " absent"));
  }
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
void classify(const Run& run, const platform::ChildOutcome& o, const OutFolder& dir, const std::string& stem,
              json& record) {
  using Kind = platform::ChildOutcome::Kind;
  const std::string log_tail = last_line(dir.read_tail(stem + ".log", kLogTailBytes));
  auto set = [&](const std::string& status, const std::string& message) {
    record["status"] = status;
    record["message"] = message;
  };
  if (o.kind == Kind::NotStarted) return set("grader_error", "the check could not start: " + o.error);
  if (o.kind == Kind::TimedOut)
    return set("timed_out", "no result within " + std::to_string(static_cast<int>(run.options.timeout)) +
                                " s (wall clock): the check was stopped");
  if (platform::stopped_at_cpu_limit(o, run.options.cpu_time))
    return set("timed_out", "no result after " + std::to_string(static_cast<int>(run.options.cpu_time)) +
                                " s of CPU time: the check was stopped (an endless loop, or an exercise far slower "
                                "than the solution)");
  const bool out_of_memory = log_tail.find("bad_alloc") != std::string::npos ||
                             log_tail.find("Cannot allocate memory") != std::string::npos;
  const std::string memory_note =
      out_of_memory ? " (over the memory limit of " + std::to_string(run.options.memory_mb) + " MB)" : "";
  if (o.kind == Kind::Signalled) return set("crashed", "the check process died: " + o.signal_name + memory_note);
  const json report = read_json(dir, stem + ".check.json", kMaxCheckJsonBytes);
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

// Keeps the diff images the --images choice asks for (in dir/<stem>), with paths relative to --out.
json kept_images(const Run& run, const OutFolder& dir, const std::string& stem, const std::string& status) {
  json images = json::array();
  const bool keep = run.options.images == "all" || (run.options.images == "failed" && status != "passed");
  if (!keep) {
    dir.remove(stem);
    return images;
  }
  const std::optional<OutFolder> folder = dir.existing_folder(stem);
  if (!folder) return images;
  for (const auto& name : folder->names()) {
    const bool diff = name.size() > 9 && name.compare(name.size() - 9, 9, "_diff.png") == 0;
    if (!diff && run.options.images != "all") {
      folder->remove(name);
      continue;
    }
    if (name.front() != '.')  // not the check's lock file
      images.push_back((folder->path() / name).lexically_relative(run.out.path()).generic_string());
  }
  return images;
}

// Why a lab cannot be graded as handed in, as {status, message}: `missing` when a file of the lab is
// not in the submission; `failed` when one is a link, leads out of the submission (a linked folder), is
// not a regular file (a FIFO, a device, a folder) or is larger than a submitted file may be. Nothing is
// read. Empty status: every file is there.
std::pair<std::string, std::string> exercise_file_problems(const Lab& lab, const fs::path& root) {
  std::string missing, refused;
  std::error_code ec;
  const std::string inside = (fs::weakly_canonical(root, ec) / "").string();
  const std::uint64_t max_bytes = UnpackLimits{}.max_file_bytes;
  for (const auto& file : lab.exercise_files) {
    const fs::path p = root / file;
    const fs::file_status st = fs::symlink_status(p, ec);
    std::string why;
    if (fs::is_symlink(st)) why = "a link; submit the file itself";
    else if (!fs::exists(st)) missing += (missing.empty() ? "" : "; ") + file + ": not in the submission";
    else if (!fs::is_regular_file(st)) why = "not a regular file; submit the file itself";
    else if (fs::weakly_canonical(p, ec).string().rfind(inside, 0) != 0) why = "leads out of the submission (a linked folder)";
    else if (fs::file_size(p, ec) > max_bytes) why = "larger than the " + std::to_string(max_bytes >> 20) + " MB a file may have; refused";
    if (!why.empty()) refused += (refused.empty() ? "" : "; ") + file + ": " + why;
  }
  if (!refused.empty()) return {"failed", refused + (missing.empty() ? "" : "; " + missing)};
  if (!missing.empty()) return {"missing", missing};
  return {};
}

void print_lab(const std::string& student, const json& r, bool recorded) {
  std::printf("%-20s lab %d %-18s %-13s %6.1f s %6.0f MB%s\n", student.c_str(), r.value("lab", -1),
              r.value("slug", "").c_str(), r.value("status", "").c_str(), r.value("seconds", 0.0),
              r.value("peak_memory_mb", 0.0), recorded ? "  (recorded before)" : "");
  std::fflush(stdout);
}

// Runs one lab's check in its own process and fills the record from how it ended. Everything the check
// writes by its path (its JSON, its log, the images folder, its temporary folder) is emptied or made
// here first, under the student's folder as opened: a link planted at one of those names is removed,
// never followed.
void check_lab(const Run& run, const Lab& lab, const fs::path& root, const OutFolder& dir, json& record) {
  const std::string stem = lab_stem(lab.number);
  dir.remove(stem + ".check.json");
  dir.remove(stem);
  dir.folder(stem);
  dir.fresh_file(stem + ".log");
  // The check's temporary files (lab 2's compiled exercise) go to a folder of the student's own, emptied
  // before and after: a check killed at a limit, or a grading run killed outright, leaves nothing in /tmp,
  // and the next run starts clean.
  dir.remove(stem + ".tmp");
  const OutFolder scratch = dir.folder(stem + ".tmp", 0700);
  const std::vector<std::string> argv = {run.self.string(), "check", "--lab", std::to_string(lab.number),
                                         "--impl", "exercise", "--submission", root.string(),
                                         "--json", (dir.path() / (stem + ".check.json")).string(),
                                         "--out", (dir.path() / stem).string()};
  const platform::ChildLimits limits{run.options.timeout, static_cast<std::uint64_t>(run.options.memory_mb) << 20,
                                     run.options.cpu_time};
  const platform::ChildOutcome o =
      platform::run_child(argv, limits, dir.path() / (stem + ".log"), {{"TMPDIR", scratch.path().string()}});
  dir.remove(stem + ".tmp");
  classify(run, o, dir, stem, record);
  record["seconds"] = o.seconds;
  record["cpu_seconds"] = o.cpu_seconds;
  record["peak_memory_mb"] = o.peak_rss_mb;
  if (o.kind == platform::ChildOutcome::Kind::Exited) record["exit"] = {{"code", o.exit_code}};
  if (o.kind == platform::ChildOutcome::Kind::Signalled) record["exit"] = {{"signal", o.signal_name}};
  record["log"] = (dir.path() / (stem + ".log")).lexically_relative(run.out.path()).generic_string();
  record["images"] = kept_images(run, dir, stem, record["status"]);
  // The student reads their files' paths as in their submission, not where it lies on this machine.
  record["message"] = relative_to(record["message"].get<std::string>(), root);
  for (auto& c : record["criteria"]) c["sentence"] = relative_to(c.value("sentence", ""), root);
}

// Grades one lab of one submission in its own process and records the result at once.
json grade_lab(const Run& run, const Lab& lab, const std::string& student, const fs::path& root, const OutFolder& dir) {
  const std::string record_name = lab_stem(lab.number) + ".json";
  json record = lab_record(lab.number, student, "grader_error", "");
  record["limits"] = {{"cpu_time_s", run.options.cpu_time}, {"timeout_s", run.options.timeout},
                      {"memory_mb", run.options.memory_mb}};
  if (const auto [status, message] = exercise_file_problems(lab, root); !status.empty()) {
    record["status"] = status;
    record["message"] = message;
  } else {
    const std::string input = input_fingerprint(run, lab, root);
    if (!run.options.again) {
      const json old = read_json(dir, record_name, kMaxCheckJsonBytes);
      if (old.is_object() && old.value("input", json()) == input && old.value("status", json()) != "grader_error") {
        print_lab(student, old, true);
        return old;
      }
    }
    record["input"] = input;
    check_lab(run, lab, root, dir, record);
  }
  dir.write(record_name, report_json(record));
  print_lab(student, record, false);
  return record;
}

// The folder to grade of one submission (an archive unpacked into dir/unpacked first); throws
// SubmissionError, in the student's terms, when it cannot be graded as given.
fs::path open_submission(const std::string& path, const OutFolder& dir, json& submission) {
  if (is_archive_name(path) && fs::is_regular_file(path)) {
    submission["kind"] = "archive";
    // Unpacked into the student's own output folder (this task's alone), not /tmp: a run killed while
    // grading leaves it there, and the next run over the same --out removes it before unpacking again.
    dir.remove("unpacked");
    const OutFolder unpacked = dir.folder("unpacked", 0700);
    unpack_archive(path, unpacked.path());
    return find_project_root(unpacked.path());
  }
  submission["kind"] = "folder";
  if (!fs::is_directory(path))
    throw SubmissionError(fs::path(path).filename().string() + ": neither a folder nor a .zip/.tar archive");
  fs::path folder = fs::absolute(path).lexically_normal();  // absolute: messages' paths are made relative to it
  if (folder.filename().empty()) folder = folder.parent_path();  // "alice/" -> "alice"
  return find_project_root(folder);
}

// One lab's result when the submission was refused, or when the grader failed on it.
json unattempted_lab(const OutFolder& dir, int lab, const std::string& student, const std::string& status,
                     const std::string& message) {
  json record = lab_record(lab, student, status, message);
  dir.write(lab_stem(lab) + ".json", report_json(record));
  print_lab(student, record, false);
  return record;
}

// Grades every lab of one submission; returns the exit code it alone would give. The grader failing on
// one lab (bad_alloc at its memory limit, a file it cannot write) makes that lab a grader_error and
// goes on with the next: one strange submission never stops the class.
int grade_submission(const Run& run, const std::string& path) {
  const std::string name = submission_name(path);
  const OutFolder dir = run.out.folder("students").folder(name);
  // The student's folder is this run's alone (the tasks of a parallel or Slurm run share --out).
  make_output_dir(dir.path().string());
  std::error_code ec;
  json submission = {{"name", name}, {"source", fs::absolute(path, ec).string()}, {"labs", run.labs}};
  fs::path root;
  std::string grader_failed;
  try {
    root = open_submission(path, dir, submission);
  } catch (const SubmissionError& e) {
    submission["error"] = e.what();
  } catch (const std::exception& e) {
    grader_failed = std::string("the grader failed to open the submission: ") + e.what();
  }
  dir.write("submission.json", report_json(submission));
  int code = kExitAllPassed;
  for (int n : run.labs) {
    json record;
    try {
      if (!grader_failed.empty()) record = unattempted_lab(dir, n, name, "grader_error", grader_failed);
      else if (submission.contains("error"))
        record = unattempted_lab(dir, n, name, "failed", "submission refused: " + submission["error"].get<std::string>());
      else record = grade_lab(run, *find_lab(n), name, root, dir);
    } catch (const std::exception& e) {
      record = lab_record(n, name, "grader_error", std::string("the grader failed on this lab: ") + e.what());
      std::fprintf(stderr, "shadowlab grade: %s lab %d: %s\n", name.c_str(), n, report_text(e.what()).c_str());
      try {
        dir.write(lab_stem(n) + ".json", report_json(record));
      } catch (const std::exception&) {  // the merge reports it as "no result"
      }
    }
    const std::string status = record.value("status", "");
    if (status == "grader_error") code = kExitGraderError;
    else if (status != "passed" && code == kExitAllPassed) code = kExitSomeFailed;
  }
  dir.remove("unpacked");
  return code;
}

// Several submissions at once: GNU parallel runs `shadowlab grade ONE --no-merge` per submission, each
// job's software rasteriser on one thread (LP_NUM_THREADS=1) so that jobs do not fight for cores.
int grade_with_parallel(const Run& run) {
  const std::string list = ".submissions.list", joblog = "parallel.joblog";
  std::string text;
  std::error_code ec;
  for (const auto& s : run.options.submissions) text += fs::absolute(s, ec).string() + '\0';
  run.out.write(list, text);
  // GNU parallel opens its job log by path: a file of our own there first, so that it never writes
  // through a link planted in --out.
  run.out.fresh_file(joblog);
  const double per_submission = static_cast<double>(run.labs.size()) * (run.options.timeout + 10.0) + 120.0;
  std::vector<std::string> argv = {"parallel", "--will-cite", "--quote", "--line-buffer", "--halt", "never",
                                   "--jobs", std::to_string(run.options.jobs), "--timeout",
                                   std::to_string(static_cast<int>(per_submission)), "--joblog",
                                   (run.out.path() / joblog).string(), "-0", "--arg-file",
                                   (run.out.path() / list).string(), run.self.string(), "grade", "--no-merge",
                                   "--out", run.out.path().string(), "--lab",
                                   run.options.labs, "--cpu-time", std::to_string(run.options.cpu_time),
                                   "--timeout", std::to_string(run.options.timeout), "--memory",
                                   std::to_string(run.options.memory_mb), "--images", run.options.images};
  if (run.options.again) argv.push_back("--again");
  argv.push_back("{}");
  std::map<std::string, std::string> env;
  if (!std::getenv("LP_NUM_THREADS")) env["LP_NUM_THREADS"] = "1";
  const platform::ChildOutcome o = platform::run_child(argv, {}, "", env);
  run.out.remove(list);
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
  run.out = OutFolder(fs::absolute(options.out_dir));
  run.self = platform::self_executable();
  return run;
}

void limit_own_memory() {
#if !defined(SHADOWLAB_GRADE_SANITIZED)
  platform::limit_own_address_space(kGraderAddressSpace);
#endif
}

}  // namespace

int run_grade(const GradeOptions& options) {
  // Not a Linux build: said at once, before --out is made. A usage error (2), not a grader error (3):
  // this build can never do it, and nothing was tried.
  if (const std::string& why = platform::grading_unavailable(); !why.empty()) {
    std::fprintf(stderr, "shadowlab grade: %s\n", why.c_str());
    return kExitUsage;
  }
  // A task of a parallel or Slurm run: it goes when whoever started it goes, and takes its checks along.
  if (options.no_merge) platform::die_with_parent();
  limit_own_memory();
  Run run;
  try {
    run = plan_run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab grade: %s\n", report_text(e.what()).c_str());
    return kExitUsage;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    int code = kExitAllPassed;
    if (!options.merge_only) {
      if (options.jobs > 1 && options.submissions.size() > 1) {
        code = grade_with_parallel(run);
      } else {
        for (const auto& s : options.submissions) {
          try {
            code = std::max(code, grade_submission(run, s));
          } catch (const std::exception& e) {  // its folder cannot be made or locked: the merge says "no result"
            std::fprintf(stderr, "shadowlab grade: %s: %s\n", submission_name(s).c_str(), report_text(e.what()).c_str());
            code = kExitGraderError;
          }
        }
      }
    }
    if (options.no_merge) return code;
    std::vector<std::string> names;
    for (const auto& s : options.submissions) names.push_back(submission_name(s));
    const MergeSummary m = merge_grades(run.out, names, run.labs);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%d submissions: %d of %d labs passed, %d missing, %d grader errors (%.0f s)\n", m.students,
                m.passed, m.labs, m.missing, m.grader_errors, seconds);
    for (const auto& f : m.written) std::printf("wrote %s\n", f.c_str());
    if (m.grader_errors > 0) return kExitGraderError;
    return m.passed == m.labs ? kExitAllPassed : kExitSomeFailed;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab grade: %s\n", report_text(one_line_error(e.what())).c_str());
    return kExitGraderError;
  }
}

}  // namespace shadowlab
