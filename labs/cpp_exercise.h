// A student's C++ exercise graded from their own file (lab 2's exercise.cpp from a submission): the
// file is compiled and linked with the lab's host (labs/cpp_exercise_host.h) into a small program of
// its own, which the check then calls over a socket. The student's code never runs inside the grader:
// a crash, an endless loop or a forged result stays in that program, which may only compute.
//
// Building refuses, as a compile error naming the student's file: compiler errors (with the student's
// file:line), includes other than the lab's offered headers and the system's, inline assembly, code
// that runs before main (global objects with constructors), and calls into the grader's code other
// than the functions the lab offers (the solution is not one of them). Compiling and linking each have
// a time limit. Calling has one too: a call that does not return in time is an endless loop.
//
// The local student flow is unchanged: without a submission, lab 2 grades the exercise compiled into
// the binary (edit, rebuild, Check).
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "labs/platform_process.h"

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

struct CppExerciseSpec {
  std::filesystem::path source;      // the student's file
  std::string display_name;          // as the student knows it: "labs/02_ortho_fit/exercise.cpp"
  std::string host;                  // the lab's host library's name: "02_ortho_fit"
  std::vector<std::string> headers;  // quoted includes it may use, relative to the data folder
  std::vector<std::string> offered;  // the grader's functions it may call ("shadowlab::orthonormal_basis")
  double compile_seconds = 60.0;     // each of compiling and linking
  double call_seconds = 10.0;        // one call, or one batch of calls
};

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

  CppExerciseSpec spec_;
  std::filesystem::path work_;
  platform::PipeChild child_;
};

}  // namespace shadowlab
