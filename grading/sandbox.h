// The operating system's walls around a student's C++ exercise while it is compiled, linked and run:
// bubblewrap (Debian's `bwrap`, a maintained sandbox tool) makes a mount namespace in which only what
// the spec lists exists, with no network, its own PID namespace that dies with the grader, no
// capabilities and an unprivileged user; a seccomp filter (made with libseccomp) is handed to
// bubblewrap, which installs it before it executes the program, so nothing the program defines can run
// before the filter or replace it. Resource limits (CPU, memory, file size) are the launcher's
// (grading/platform_process.h, ChildLimits), inherited through bubblewrap.
//
// Linux only (grading/sandbox.cpp): elsewhere, and where the kernel or the machine does not let
// bubblewrap make its namespaces, `sandbox_unavailable()` says why and nothing runs unconfined.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "grading/platform_process.h"

namespace shadowlab::platform {

// What the program may call, installed before exec.
enum class SyscallFilter {
  Toolchain,  // a compiler, linker or binutils on hostile text: files and processes inside the sandbox;
              // no sockets, no tracing, no mounting, no kernel keys, no new namespaces
  Computing,  // a student's program: memory, time, its open descriptors and leaving; no files opened,
              // no processes or threads, no sockets (anything else kills it with SIGSYS)
};

struct SandboxMount {
  std::filesystem::path host;  // a file or folder of ours
  std::string inside;          // where the program sees it (an absolute path)
  bool writable = false;
};

struct SandboxSpec {
  std::vector<SandboxMount> mounts;
  bool system_toolchain = false;      // the system's /usr (compilers, headers, libraries) read-only, with
                                      // /bin, /lib... as on the host, a private /tmp and a minimal /dev
  std::uint64_t tmp_bytes = 64 << 20;  // the size of that /tmp
  std::string chdir = "/";
  SyscallFilter filter = SyscallFilter::Computing;
  std::vector<std::pair<std::string, std::string>> env = {};  // set in the sandbox's empty environment
};

// A program's command line wrapped in bubblewrap, and the filter's descriptor it reads (which the
// launcher must let the child inherit: `inherited()`); the descriptor closes with the object.
class SandboxCommand {
 public:
  // Throws std::runtime_error when the filter cannot be made.
  SandboxCommand(const SandboxSpec& spec, const std::vector<std::string>& argv);
  ~SandboxCommand();
  SandboxCommand(const SandboxCommand&) = delete;
  SandboxCommand& operator=(const SandboxCommand&) = delete;

  const std::vector<std::string>& argv() const { return argv_; }
  std::vector<int> inherited() const { return {filter_fd_}; }

 private:
  std::vector<std::string> argv_;
  int filter_fd_ = -1;
};

// How the program inside ended, from how bubblewrap did: bubblewrap exits with 128 + N when the
// program died of signal N (SIGSYS from the filter, SIGXCPU or SIGXFSZ at a limit, a crash).
ChildOutcome inner_outcome(ChildOutcome bubblewrap);

// Empty when sandboxes can be made here; otherwise one sentence saying why not and what is needed
// (bubblewrap missing, namespaces refused by the kernel, not Linux). Probed once per process by running
// a trivial program in the same sandbox the exercises get.
const std::string& sandbox_unavailable();

}  // namespace shadowlab::platform
