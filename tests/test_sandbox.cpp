// The sandbox of submitted C++ exercises (grading/sandbox.h, grading/cpp_exercise.h), attacked the way a
// hostile student would: each case is lab 2's exercise with something added, graded with the early
// screens off (SandboxAttack) so that what holds is the operating system's sandbox alone, and with them
// on (ScreenedAttack) for the status a student gets. Each case proves that nothing outside was written
// (a canary folder's listing and content), read (a secret's text appears in no message or log) or left
// running (no process of the exercise outlives it).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include <sys/prctl.h>
#include <unistd.h>

#include "labs/02_ortho_fit/ortho_fit.h"
#include "grading/cpp_exercise.h"
#include "grading/sandbox.h"

namespace shadowlab {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A right answer of the exam corpus, written with the offered orthonormal_basis.
std::string right_answer() {
  return read_text(fs::path(SHADOWLAB_SOURCE_DIR) / "tests/answers/02_ortho_fit/right/lookat_basis_up__exercise.cpp");
}

// Everything under `dir` with its bytes: what "nothing was written" compares.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    files[e.path().string()] = e.is_regular_file() ? read_text(e.path()) : "<folder>";
  return files;
}

// The parent of process `pid` (field 4 of /proc/PID/stat, after the parenthesised name), 0 if gone.
int parent_of(int pid) {
  const std::string stat = read_text("/proc/" + std::to_string(pid) + "/stat");
  const auto close = stat.rfind(')');
  if (close == std::string::npos) return 0;
  std::istringstream rest(stat.substr(close + 1));
  std::string state;
  int parent = 0;
  rest >> state >> parent;
  return parent;
}

// Processes of ours whose command line names the exercise's program (inside the sandbox, /exercise).
// This test process is a subreaper (SetUp), so what a sandbox leaves behind stays our descendant, and
// other tests' exercises running beside us are not counted.
int exercise_processes() {
  int n = 0;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string cmd = read_text(e.path() / "cmdline"), name = e.path().filename().string();
    if (cmd.rfind("/exercise", 0) != 0 || cmd.find('\0') != 9 || name.find_first_not_of("0123456789") != std::string::npos)
      continue;
    for (int pid = std::stoi(name); pid > 1; pid = parent_of(pid))
      if (pid == ::getpid()) {
        ++n;
        break;
      }
  }
  return n;
}

// What an attack got: the status it was given (or "answered"), the message, the program's log.
struct Outcome {
  std::string status, message;
};

class Sandbox : public ::testing::Test {
 protected:
  void SetUp() override {
    if (const std::string& why = platform::sandbox_unavailable(); !why.empty()) GTEST_SKIP() << why;
    ::prctl(PR_SET_CHILD_SUBREAPER, 1);
    std::random_device random;
    root_ = fs::temp_directory_path() / ("shadowlab-sandbox-test-" + std::to_string(random()));
    outside_ = root_ / "outside";
    fs::create_directories(outside_);
    secret_ = "secret-" + std::to_string(random()) + "-" + std::to_string(random());
    std::ofstream(outside_ / "secret.txt") << secret_ << "\n";
    std::ofstream(outside_ / "canary.json") << "{\"status\": \"failed\"}\n";
    before_ = snapshot(outside_);
  }
  void TearDown() override {
    if (root_.empty()) return;
    EXPECT_EQ(snapshot(outside_), before_) << "something outside the sandbox was written";
    // A killed sandbox's namespace is torn down by the kernel after its first process is reaped: given
    // a moment (at most 2 s), nothing of the exercise may be left.
    int left = exercise_processes();
    for (int i = 0; i < 40 && left > 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      left = exercise_processes();
    }
    EXPECT_EQ(left, 0) << "a process of the exercise outlived it";
    std::error_code ec;
    fs::remove_all(root_, ec);
  }

  // $OUT and $SECRET in `source` become the canary folder and the secret's path.
  std::string expand(std::string source) const {
    for (const auto& [key, value] : {std::pair<std::string, std::string>{"$OUT", outside_.string()},
                                     {"$SECRET", (outside_ / "secret.txt").string()}})
      for (auto at = source.find(key); at != std::string::npos; at = source.find(key, at))
        source.replace(at, key.size(), value);
    return source;
  }

  // Lab 2's exercise (or, with `host` "12_cascaded_shadow_maps" or "15_two_lights", lab 12's or 15's) holding
  // `source`.
  CppExerciseSpec spec(const std::string& source, bool screen, const std::string& host = "02_ortho_fit") {
    const std::string name = "labs/" + host + "/exercise.cpp";
    const fs::path file = root_ / "submission" / name;
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << expand(source);
    CppExerciseSpec s;
    s.source = file;
    s.display_name = name;
    s.host = host;
    s.headers = {"labs/02_ortho_fit/ortho_fit.h", "labs/12_cascaded_shadow_maps/cascades_lab.h",
                 "labs/15_two_lights/flashlight_fit.h", "core/light.h", "core/scene.h", "core/cascades.h",
                 "core/params.h"};
    s.offered = {"shadowlab::orthonormal_basis", "shadowlab::fixed_tutorial_ortho", "shadowlab::direction_from_angles"};
    s.screen = screen;
    s.compile_seconds = 20.0;
    s.call_seconds = 3.0;
    return s;
  }

  // Builds and calls the exercise once; the outcome with the secret checked for in everything said.
  Outcome attack(const std::string& source, bool screen = false) {
    Outcome o;
    try {
      CppExercise program(spec(source, screen));
      const FitCall call{{-1, -1, -1}, {1, 1, 1}, {0.3f, 1.0f, 0.2f}};
      const FitAnswer answer = program.call<FitAnswer>(call);
      o.status = "answered";
      o.message = std::to_string(answer.world_size[0]);
    } catch (const ExerciseError& e) {
      o.status = e.status();
      o.message = e.what();
    } catch (const std::exception& e) {
      o.status = "grader_error";
      o.message = e.what();
    }
    EXPECT_EQ(o.message.find(secret_), std::string::npos) << "the secret was read: " << o.message;
    EXPECT_EQ(o.message.find("root:x:0:0"), std::string::npos) << "/etc/passwd was read: " << o.message;
    if (expand(source).find(root_.string()) == std::string::npos) {  // unless the student wrote it
      EXPECT_EQ(o.message.find(root_.string()), std::string::npos) << "the grader's path was shown: " << o.message;
    }
    return o;
  }

  fs::path root_, outside_;
  std::string secret_;
  std::map<std::string, std::string> before_;
};

TEST_F(Sandbox, ARightAnswerBuildsAndAnswersInside) {
  const Outcome o = attack(right_answer());
  EXPECT_EQ(o.status, "answered") << o.message;
}

// The program holds only the core functions it calls: not the solution (fit_light_ortho, in the same
// file as the offered orthonormal_basis), which an answer could otherwise reach through a function
// pointer at a known distance from an offered function's address.
// Lab 12's likewise: practical_splits and fit_cascade_sphere (core/cascades.cpp); lab 15's: flashlight_view
// (core/flashlight.cpp, the renderer's default), of which only the exercise's own flashlight_view_exercise
// may be there.
TEST_F(Sandbox, TheSolutionIsNotInTheProgram) {
  const fs::path answers = fs::path(SHADOWLAB_SOURCE_DIR) / "tests/answers";
  struct Case {
    std::string host, source, present;  // `present`: a function the program holds (what it calls, or its own)
  };
  const Case cases[] = {
      {"02_ortho_fit", right_answer(), "shadowlab::orthonormal_basis"},
      {"12_cascaded_shadow_maps", read_text(answers / "12_cascaded_shadow_maps/right/round_to_nearest__exercise.cpp"),
       "shadowlab::orthonormal_basis"},
      {"15_two_lights", read_text(answers / "15_two_lights/right/lookat_safe_up__exercise.cpp"),
       "shadowlab::flashlight_view_exercise("}};
  for (const auto& [host, source, present] : cases) {
    CppExercise program(spec(source, true, host));
    const fs::path symbols = root_ / "symbols.txt";
    ASSERT_EQ(platform::run_child({"nm", "-C", program.program().string()}, {30.0, 0, 0.0, 0}, symbols).exit_code, 0);
    const std::string listed = read_text(symbols);
    EXPECT_NE(listed.find(present), std::string::npos) << host << ": " << present << " is not listed";
    for (const char* solution :
         {"fit_light_ortho", "practical_splits", "fit_cascade_sphere", "flashlight_view(", "flashlight_spec"})
      EXPECT_EQ(listed.find(solution), std::string::npos) << host << ": " << solution << " was linked in";
  }
}

// The exercise's own function, doing `body` before it answers.
std::string exercise_doing(const std::string& includes, const std::string& body) {
  return includes + "\n#include \"labs/02_ortho_fit/ortho_fit.h\"\nnamespace shadowlab {\n"
                    "LightView ortho_fit_exercise(const Bounds& b, const glm::vec3& d) {\n" + body +
         "\n  (void)b;\n  return fixed_tutorial_ortho(d);\n}\n}\n";
}

// Code that reads the secret and prints it to the log (which the student's messages quote).
constexpr const char* kReadSecret =
    "  if (std::FILE* f = std::fopen(\"$SECRET\", \"r\")) { char b[64] = {}; std::fread(b, 1, 63, f); std::fputs(b, stderr); }\n";

void expect_killed_by_the_filter(const Outcome& o) {
  EXPECT_EQ(o.status, "crashed") << o.message;
  EXPECT_NE(o.message.find("SIGSYS"), std::string::npos) << o.message;
}

// A main() of the student's own in place of the host's: it runs before any filter of the host, so
// only the launcher's filter and the mount namespace stand between it and the grader's files.
TEST_F(Sandbox, AMainOfItsOwnCannotWriteReadOrLeaveAProcess) {
  const std::string evil = exercise_doing("#include <cstdio>\n#include <unistd.h>", "") +
                           "int main() {\n"
                           "  if (std::FILE* f = std::fopen(\"$OUT/canary.json\", \"w\")) std::fputs(\"{\\\"status\\\": \\\"passed\\\"}\", f);\n" +
                           kReadSecret +
                           "  if (::fork() == 0) { ::setsid(); ::sleep(60); }\n"
                           "  return 0;\n}\n";
  expect_killed_by_the_filter(attack(evil));
  EXPECT_EQ(attack(evil, true).status, "compile_error");
}

// A C function the host calls before it installs its own filter (dup), replaced by one that writes
// outside. (seccomp_load itself cannot be replaced: the static link refuses a second definition.)
TEST_F(Sandbox, ReplacingACallTheHostMakesBeforeItsFilterGainsNothing) {
  const std::string evil = exercise_doing("#include <cstdio>\n#include <fcntl.h>\n#include <unistd.h>", kReadSecret) +
                           "extern \"C\" int dup(int fd) {\n"
                           "  int out = ::open(\"$OUT/forged.json\", O_WRONLY | O_CREAT, 0644);\n"
                           "  if (out >= 0) ::write(out, \"passed\", 6);\n"
                           "  return ::fcntl(fd, F_DUPFD, 0);\n}\n";
  expect_killed_by_the_filter(attack(evil));
  const Outcome screened = attack(evil, true);
  EXPECT_EQ(screened.status, "compile_error");
  EXPECT_NE(screened.message.find("defines dup"), std::string::npos) << screened.message;
}

// The preprocessor's other spellings of an include, and the assembler's: the solution's source and the
// system's files are not in the sandbox to be included.
TEST_F(Sandbox, IncludesOfAnySpellingFindNothingOfTheGraders) {
  const std::string right = right_answer();
  for (const std::string& trick :
       {std::string("%:include \"core/light.cpp\""), std::string("#import \"core/light.cpp\""),
        std::string("#inc\\\nlude \"core/light.cpp\""), std::string("#include \"../../core/light.cpp\""),
        std::string("#include \"/etc/passwd\""), std::string("#include \"$SECRET\""),
        std::string("asm(\".incbin \\\"$SECRET\\\"\");"), std::string("__asm__(\".incbin \\\"/etc/passwd\\\"\");")}) {
    for (bool screen : {false, true}) {
      const Outcome o = attack(trick + "\n" + right, screen);
      EXPECT_EQ(o.status, "compile_error") << trick << (screen ? " (screened)" : "") << ": " << o.message;
      if (!screen) {
        EXPECT_TRUE(o.message.find("No such file") != std::string::npos || o.message.find("not found") != std::string::npos)
            << trick << ": " << o.message;
      }
    }
  }
}

TEST_F(Sandbox, TheEnvironmentAndTheProcessTableAreEmpty) {
  const Outcome o = attack(exercise_doing("#include <cstdlib>\n#include <dirent.h>",
                                          "  if (std::getenv(\"HOME\") || std::getenv(\"TMPDIR\") || std::getenv(\"SHADOWLAB_SETTINGS\"))"
                                          " return LightView{};\n  ::opendir(\"/proc\");"));
  expect_killed_by_the_filter(o);  // the environment was empty; listing /proc is not allowed
}

TEST_F(Sandbox, PrintingWithoutEndStopsAtTheOutputLimit) {
  const Outcome o = attack(exercise_doing("#include <cstdio>", "  for (;;) std::puts(\"spam spam spam spam spam\");"));
  EXPECT_EQ(o.status, "crashed") << o.message;
  EXPECT_NE(o.message.find("SIGXFSZ"), std::string::npos) << o.message;
}

TEST_F(Sandbox, MemoryIsLimited) {
  const Outcome o = attack(exercise_doing("#include <vector>", "  std::vector<char> big(3ull << 30, 1); if (big[7]) {}"));
  EXPECT_EQ(o.status, "crashed") << o.message;
  EXPECT_NE(o.message.find("SIGABRT"), std::string::npos) << o.message;  // std::bad_alloc, not a full machine
}

TEST_F(Sandbox, AnEndlessLoopTimesOut) {
  const auto start = std::chrono::steady_clock::now();
  const Outcome o = attack(exercise_doing("", "  for (volatile int i = 0;; i = i + 1) {}"));
  EXPECT_EQ(o.status, "timed_out") << o.message;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30.0);
}

// The compiler itself kept to its limits: a preprocessor bomb (16^8 = 2^32 tokens) is stopped by the
// memory or the time limit, not waited for.
TEST_F(Sandbox, ACompilerBombIsStopped) {
  const auto start = std::chrono::steady_clock::now();
  const Outcome o = attack("#define A(x) x x x x x x x x x x x x x x x x\n#define B(x) A(A(A(A(x))))\n"
                           "#define C(x) B(B(x))\nint bomb = C(+1);\n" + right_answer());
  EXPECT_TRUE(o.status == "timed_out" || (o.status == "compile_error" && o.message.find("memory") != std::string::npos))
      << o.status << ": " << o.message;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
}

TEST_F(Sandbox, ALinkedExerciseFileIsRefusedUnread) {
  const CppExerciseSpec s = spec("", false);
  const fs::path file = s.source;
  fs::remove(file);
  fs::create_symlink(outside_ / "secret.txt", file);
  try {
    CppExercise program(s);
    FAIL() << "a linked exercise was built";
  } catch (const ExerciseError& e) {
    EXPECT_EQ(e.status(), "compile_error");
    EXPECT_NE(std::string(e.what()).find("is a link"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(secret_), std::string::npos);
  }
}

}  // namespace
}  // namespace shadowlab

namespace shadowlab {
namespace {

// Where no sandbox can be made, a C++ lab is not built at all: a grader error that says what is needed,
// never the student's code compiled or run unconfined (a file that does not compile is not even
// reported as a compile error). Made here with a PATH that has no bubblewrap, and with a bubblewrap that
// fails the way it does where the kernel refuses user namespaces.
void expect_refused(const fs::path& path_dir, const std::string& words) {
  const fs::path dir = path_dir.string() + "-check";  // each case its own (CTest runs them side by side)
  fs::remove_all(dir);
  fs::create_directories(dir / "submission/labs/02_ortho_fit");
  std::ofstream(dir / "submission/labs/02_ortho_fit/exercise.cpp") << "this is not C++\n";
  const platform::ChildOutcome o = platform::run_child(
      {SHADOWLAB_BINARY, "check", "--lab", "2", "--impl", "exercise", "--submission", (dir / "submission").string(), "--json",
       (dir / "check.json").string()},
      {120.0, 0, 0.0, 0}, dir / "check.log", {{"PATH", path_dir.string()}});
  const std::string said = read_text(dir / "check.log") + read_text(dir / "check.json");
  EXPECT_EQ(o.kind, platform::ChildOutcome::Kind::Exited);
  EXPECT_EQ(o.exit_code, 3) << said;  // a grader error, not the student's
  EXPECT_NE(said.find("grader_error"), std::string::npos) << said;
  EXPECT_NE(said.find(words), std::string::npos) << said;
  EXPECT_EQ(said.find("error: expected"), std::string::npos) << "the file was compiled: " << said;
  fs::remove_all(dir);
}

TEST(SandboxMissing, WithoutBubblewrapCppLabsAreRefused) {
  const fs::path empty = fs::temp_directory_path() / "shadowlab-no-bwrap";
  fs::create_directories(empty);
  expect_refused(empty, "bubblewrap (bwrap) is not installed");
  fs::remove_all(empty);
}

TEST(SandboxMissing, WithoutNamespacesCppLabsAreRefused) {
  const fs::path fake = fs::temp_directory_path() / "shadowlab-fake-bwrap";
  fs::create_directories(fake);
  std::ofstream(fake / "bwrap") << "#!/bin/sh\necho 'bwrap: No permissions to create new namespace' >&2\nexit 1\n";
  fs::permissions(fake / "bwrap", fs::perms::owner_all);
  expect_refused(fake, "bubblewrap cannot make its sandbox here (bwrap: No permissions to create new namespace)");
  fs::remove_all(fake);
}

}  // namespace
}  // namespace shadowlab
