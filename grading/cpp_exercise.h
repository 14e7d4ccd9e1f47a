// A student's C++ exercise graded from their own file (lab 2's exercise.cpp from a submission): the
// file is compiled and linked with the lab's host (grading/cpp_exercise_host.h) into a small static program
// of its own, which the check then calls over a socket. The student's code never runs inside the grader.
//
// The defence is the operating system's (grading/sandbox.h): compiling, inspecting and linking run in
// bubblewrap sandboxes that hold the system's /usr, the lab's headers and a copy of the student's file,
// nothing else of ours (no solution or renderer sources, no --out, no home, no /etc); the program runs
// in one that holds only itself, under a seccomp filter installed before it starts (it may only
// compute), as nobody, with no network, in a PID namespace that dies with the grader, and under CPU,
// memory and output-size limits. Where no sandbox can be made, the exercise is not built at all.
//
// Before that, friendly refusals with a message naming the student's file (`screen`): includes other
// than the lab's offered headers and the system's, inline assembly, definitions of the grader's or the
// system's functions (main, a C function), code that runs before main, calls into the grader's code
// other than the functions the lab offers. Compiling and linking each have a time limit; so does a call.
//
// The local student flow: without a submission, a lab grades the exercise compiled into the binary while
// the file on disk is that copy, and builds the file here, like a submission's, once it was edited
// (CheckContext::grade_edited_cpp_files, grading/check.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "grading/platform_process.h"

namespace shadowlab {

// A failure of the student's code, with the status a grade records for it: "compile_error",
// "crashed" or "timed_out". The message names the student's file.
class ExerciseError : public std::runtime_error {
 public:
  ExerciseError(std::string status, const std::string& message) : std::runtime_error(message), status_(std::move(status)) {}
  const std::string& status() const { return status_; }

 private:
  std::string status_;
};

// The largest C++ exercise file read (a submission's, or an edited one on disk): an exercise is a few KB.
inline constexpr std::uint64_t kMaxExerciseSourceBytes = 1 << 20;

// A text file's bytes without carriage returns: a checkout with CRLF line ends and the copy the compiler
// embedded (which reads them as plain line ends) are the same file.
inline std::string without_carriage_returns(std::string text) {
  std::erase(text, '\r');
  return text;
}

struct CppExerciseSpec {
  std::filesystem::path source;      // the student's file
  std::string display_name;          // as the student knows it: "labs/02_ortho_fit/exercise.cpp"
  std::string host;                  // the lab's host library's name: "02_ortho_fit"
  std::vector<std::string> headers;  // quoted includes it may use, relative to the data folder
  std::vector<std::string> offered;  // the grader's functions it may call ("shadowlab::orthonormal_basis")
  double compile_seconds = 60.0;     // each of compiling and linking
  double call_seconds = 10.0;        // one call, or one batch of calls
  // The early, friendly refusals (includes, inline assembly, calls and definitions the lab does not
  // allow, code before main). The sandbox holds without them; tests turn them off to prove it.
  bool screen = true;
  // A GL exercise (lab 0's depth framebuffer): the program is linked against the system's libepoxy and
  // libEGL, and runs with the system's /usr read-only (Mesa's llvmpipe and its configuration), under the
  // toolchain's filter until its host has made a headless OpenGL context; then the host confines itself
  // to computing and rendering (grading/cpp_exercise_host.h) before it calls the student's functions.
  bool renders = false;
};

// Empty where a C++ exercise of the lab host `host` ("00_basic_shadow_map") can be built and run here;
// otherwise the one sentence saying why not (no sandbox; a GL exercise's host needs a build with EGL).
std::string cpp_exercise_unavailable(const std::string& host);

// The compiler every exercise is built with (the system's, CMake's) and the flags, as an argv start.
std::vector<std::string> exercise_compiler_command();
// The compiler's and linker's words as the student can read them: `source` (as given and canonical) named
// `display_name`, the work folder, the data folder and the source tree taken out of every path; at most
// `max_lines` lines (then how many more there were).
std::string compiler_words(std::string log, const std::filesystem::path& source, const std::string& display_name,
                           const std::filesystem::path& work, std::size_t max_lines = 30);

class CppExercise {
 public:
  // Builds and starts the student's program; throws ExerciseError (or std::runtime_error when the
  // grader itself is broken: no compiler, no host library).
  explicit CppExercise(CppExerciseSpec spec);
  ~CppExercise();

  // One request and its reply; throws ExerciseError ("crashed", "timed_out") when the program fails.
  template <typename Reply, typename Request>
  Reply call(const Request& request) {
    Reply reply;
    call_raw(&request, sizeof request, &reply, sizeof reply);
    return reply;
  }
  // The program as built (for tests that look inside it).
  std::filesystem::path program() const { return work_ / "out" / "exercise"; }

  // Many requests in one exchange (one round trip instead of one each), within the same time limit.
  template <typename Reply, typename Request>
  std::vector<Reply> call_many(const std::vector<Request>& requests) {
    std::vector<Reply> replies(requests.size());
    call_raw(requests.data(), sizeof(Request) * requests.size(), replies.data(), sizeof(Reply) * replies.size());
    return replies;
  }

 private:
  void call_raw(const void* request, std::size_t request_size, void* reply, std::size_t reply_size);
  void build();
  void screen_object(const std::filesystem::path& out) const;

  CppExerciseSpec spec_;
  std::filesystem::path work_;
  platform::PipeChild child_;
};

// A lab's wrapper of a submitted file's program (it takes the file in its constructor), built once per
// file and thread: a check asks for a lab's hooks several times, and each build is a compile. Per thread,
// because the program dies with the thread that started it (PR_SET_PDEATHSIG, bubblewrap's
// --die-with-parent): the window runs each Check on a thread of its own, and a second Check of the same
// edited file would otherwise call the program the first one's thread took with it.
template <typename Program>
std::shared_ptr<Program> built_once(const std::filesystem::path& file) {
  thread_local std::map<std::filesystem::path, std::shared_ptr<Program>> built;
  std::shared_ptr<Program>& program = built[file];
  if (!program) program = std::make_shared<Program>(file);
  return program;
}

}  // namespace shadowlab
