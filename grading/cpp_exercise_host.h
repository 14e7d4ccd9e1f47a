// The grader's half inside a student's compiled C++ exercise (grading/cpp_exercise.h builds the program):
// a main() that answers fixed-size requests, one reply each, until its input ends. Before the first
// request it confines itself to computing (grading/platform_process.h), and the student's output
// (printf, std::cout) goes to the log, never into the replies.
#pragma once

#include <cstddef>

namespace shadowlab {

// Sets up the descriptors and the confinement; returns the descriptor to talk on, or -1 (reason on stderr).
// `prepare` (a GL exercise's host: its OpenGL context, grading/gl_exercise_host.h) runs between the two,
// before any of the student's code; false stops the host. A host that prepares is confined as rendering
// (platform::confine_to_computing).
int exercise_host_begin(bool (*prepare)() = nullptr);
// Reads exactly `size` bytes; false at end of input.
bool exercise_host_read(int fd, void* data, std::size_t size);
// Writes all `size` bytes; false if the grader has gone.
bool exercise_host_write(int fd, const void* data, std::size_t size);

// The loop: main() of a lab's host is `return serve_exercise<Request, Reply>(answer);`.
template <typename Request, typename Reply, typename Answer>
int serve_exercise(Answer&& answer, bool (*prepare)() = nullptr) {
  const int fd = exercise_host_begin(prepare);
  if (fd < 0) return 3;
  Request request;
  while (exercise_host_read(fd, &request, sizeof request)) {
    const Reply reply = answer(request);
    if (!exercise_host_write(fd, &reply, sizeof reply)) return 0;
  }
  return 0;
}

}  // namespace shadowlab
