#include "grading/cpp_exercise_host.h"

#include <cerrno>
#include <cstdio>
#include <string>

#include <unistd.h>

#include "grading/platform_process.h"

namespace shadowlab {

int exercise_host_begin(bool (*prepare)()) {
  // The grader's socket is on 0 and 1; keep it on a descriptor of our own and point 1 at the log (2),
  // so that whatever the exercise prints cannot be taken for a reply.
  const int fd = ::dup(0);
  if (fd < 0 || ::dup2(2, 1) < 0) {
    std::perror("exercise host");
    return -1;
  }
  ::close(0);
  if (prepare && !prepare()) return -1;
  std::string error;
  if (!platform::confine_to_computing(error, prepare != nullptr)) {
    std::fprintf(stderr, "exercise host: %s\n", error.c_str());
    return -1;
  }
  return fd;
}

bool exercise_host_read(int fd, void* data, std::size_t size) {
  auto* p = static_cast<char*>(data);
  for (std::size_t got = 0; got < size;) {
    const ssize_t n = ::read(fd, p + got, size - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += static_cast<std::size_t>(n);
  }
  return true;
}

bool exercise_host_write(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const char*>(data);
  for (std::size_t sent = 0; sent < size;) {
    const ssize_t n = ::write(fd, p + sent, size - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace shadowlab
