// What the grading sandbox (grading/sandbox.h) costs a C++ lab's check, measured side by side in one run:
//   bench_sandbox SHADOWLAB_BINARY [RUNS]
// For labs 2 and 12, with a right answer of the exam corpus as the submission:
// - the lab's whole check (`shadowlab check --lab N --submission DIR`, sandbox included), median of RUNS;
// - what the sandbox adds to it: its two start-ups (the build's sandbox, holding the system's /usr, and
//   the program's, holding only the program), each timed against the same program started directly,
//   pair by pair; and the static link the program's sandbox needs, against a dynamic link of the same
//   object, pair by pair.
// Prints a table; asserts nothing (times belong in a benchmark, not in a test that flakes).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "grading/platform_process.h"
#include "grading/sandbox.h"

namespace fs = std::filesystem;
using namespace shadowlab::platform;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

double seconds_of(const std::vector<std::string>& argv, const fs::path& log, const std::vector<int>& inherit = {}) {
  const auto start = std::chrono::steady_clock::now();
  const ChildOutcome o = run_child(argv, {120.0, 0, 0.0, 0}, log, {}, inherit);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (o.kind != ChildOutcome::Kind::Exited || (o.exit_code != 0 && o.exit_code != 1)) {
    std::fprintf(stderr, "bench_sandbox: %s did not run (see %s)\n", argv.front().c_str(), log.c_str());
    std::exit(3);
  }
  return s;
}

// Median over `pairs` of (sandboxed - direct), alternating the two.
double startup_cost(const SandboxSpec& spec, const std::vector<std::string>& inside,
                    const std::vector<std::string>& direct, int pairs, const fs::path& log) {
  std::vector<double> extra;
  for (int i = 0; i < pairs; ++i) {
    const SandboxCommand command(spec, inside);
    const double boxed = seconds_of(command.argv(), log, command.inherited());
    extra.push_back(boxed - seconds_of(direct, log));
  }
  return median(extra);
}

struct LabCase {
  int number;
  std::string folder;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_sandbox SHADOWLAB_BINARY [RUNS]\n");
    return 2;
  }
  if (!sandbox_unavailable().empty()) {
    std::fprintf(stderr, "bench_sandbox: %s\n", sandbox_unavailable().c_str());
    return 3;
  }
  const std::string shadowlab = fs::absolute(argv[1]).string();
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const fs::path work = make_private_temp_dir("shadowlab-bench-sandbox"), log = work / "run.log";
  const std::string cxx = fs::canonical(SHADOWLAB_CXX).string();

  SandboxSpec toolchain;
  toolchain.system_toolchain = true;
  toolchain.filter = SyscallFilter::Toolchain;
  const double toolchain_start = startup_cost(toolchain, {"/usr/bin/true"}, {"/usr/bin/true"}, 4 * runs, log);

  std::printf("%-4s %9s %16s %16s %14s %13s %7s\n", "lab", "check s", "build sandbox ms", "run sandbox ms",
              "static link ms", "sandbox ms", "share");
  for (const LabCase& lab : {LabCase{2, "02_ortho_fit"}, LabCase{12, "12_cascaded_shadow_maps"}}) {
    // The submission: the corpus's first right answer.
    const fs::path sub = work / ("lab" + std::to_string(lab.number)), file = sub / "labs" / lab.folder / "exercise.cpp";
    fs::create_directories(file.parent_path());
    for (const auto& e : fs::directory_iterator(fs::path(SHADOWLAB_SOURCE_DIR) / "tests/answers" / lab.folder / "right")) {
      fs::copy_file(e.path(), file, fs::copy_options::overwrite_existing);
      break;
    }
    std::vector<double> check;
    for (int i = 0; i < runs; ++i)
      check.push_back(seconds_of({shadowlab, "check", "--lab", std::to_string(lab.number), "--impl", "exercise",
                                  "--submission", sub.string()},
                                 log));

    // The same object linked statically (what the program's sandbox needs) and dynamically.
    const fs::path host_dir = SHADOWLAB_EXERCISE_HOST_DIR, object = work / "exercise.o";
    std::vector<std::string> compile = {cxx};
    std::istringstream flags(SHADOWLAB_EXERCISE_CXX_FLAGS);
    for (std::string f; flags >> f;) compile.push_back(f);
    compile.insert(compile.end(), {"-iquote", SHADOWLAB_EXERCISE_SOURCE_DIR, "-c", file.string(), "-o", object.string()});
    seconds_of(compile, log);
    const std::string host = (host_dir / ("libshadowlab_exercise_host_" + lab.folder + ".a")).string();
    auto link = [&](bool fixed, const fs::path& to) {
      std::vector<std::string> a = {cxx, object.string(), host, SHADOWLAB_CORE_LIBRARY, "-lseccomp", "-o", to.string()};
      if (fixed) a.insert(a.begin() + 1, "-static");
      return seconds_of(a, log);
    };
    std::vector<double> static_extra;
    for (int i = 0; i < runs; ++i) static_extra.push_back(link(true, work / "exercise") - link(false, work / "dynamic"));

    SandboxSpec alone;
    alone.mounts = {{work / "exercise", "/exercise"}};
    alone.filter = SyscallFilter::Computing;
    const double run_start = startup_cost(alone, {"/exercise"}, {(work / "exercise").string()}, 4 * runs, log);

    const double cost = toolchain_start + run_start + median(static_extra), check_s = median(check);
    std::printf("%-4d %9.3f %16.1f %16.1f %14.1f %13.1f %6.1f%%\n", lab.number, check_s, 1e3 * toolchain_start,
                1e3 * run_start, 1e3 * median(static_extra), 1e3 * cost, 100.0 * cost / check_s);
  }
  std::error_code ec;
  fs::remove_all(work, ec);
  return 0;
}
