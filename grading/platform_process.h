// What grading needs from the operating system, in one file: run a child program under a wall-clock
// limit and a memory limit and say how it ended; talk to a child over pipes; confine a child to
// computing; find our own executable; make a private temporary folder.
//
// The implementation is POSIX (fork/exec, setrlimit, process groups, wait4) with Linux extras
// (prctl's parent-death signal, seccomp through libseccomp). Each function says what it would be
// elsewhere; grading runs on the TA's Linux machine (or WSL) or a Linux cluster, students' Windows and
// macOS machines only build the window and run `check` on their own work, which needs none of this:
// there the functions build (platform_process.cpp's fallback) and say that grading needs Linux.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace shadowlab::platform {

struct ChildLimits {
  double wall_seconds = 0.0;               // 0: none. The whole process group is killed at the limit.
  std::uint64_t address_space_bytes = 0;   // 0: none. Allocations beyond it fail (RLIMIT_AS).
  double cpu_seconds = 0.0;                // 0: none. CPU time of the process, all its threads: SIGXCPU at the
                                           // limit, SIGKILL 5 s later (RLIMIT_CPU). The same whatever the load.
  std::uint64_t file_size_bytes = 0;       // 0: none. No file it writes (its log included) grows beyond it:
                                           // SIGXFSZ (RLIMIT_FSIZE).
};

struct ChildOutcome {
  enum class Kind { Exited, Signalled, TimedOut, NotStarted };
  Kind kind = Kind::NotStarted;
  int exit_code = 0;          // Exited
  int signal = 0;             // Signalled
  std::string signal_name;    // "SIGSEGV (segmentation fault)"
  std::string error;          // NotStarted: why
  double seconds = 0.0;       // wall clock
  double cpu_seconds = 0.0;   // user + system time of the child and its waited-for descendants
  double peak_rss_mb = 0.0;   // the child's (and its waited-for descendants') peak resident memory
};

// Runs argv (argv[0] a path or a name in PATH) in its own process group, stdout and stderr into
// `log_file` (empty: ours), stdin from /dev/null, with `env`
// added to the environment, and waits for it under `limits`. The child dies with this process (Linux:
// PR_SET_PDEATHSIG), so a grading run killed from outside leaves no orphans.
// Elsewhere: Windows CreateProcess in a Job object (JOB_OBJECT_LIMIT_PROCESS_MEMORY,
// JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE, TerminateJobObject at the deadline); macOS the same POSIX calls
// (RLIMIT_AS is not enforced there: the memory limit becomes advisory). `inherit`: descriptors of ours
// (opened close-on-exec) that the program gets under the same numbers (a sandbox's filter).
ChildOutcome run_child(const std::vector<std::string>& argv, const ChildLimits& limits,
                       const std::filesystem::path& log_file, const std::map<std::string, std::string>& env = {},
                       const std::vector<int>& inherit = {});

// A child whose stdin and stdout are pipes to us (a student's compiled exercise answering calls).
// Its stderr goes to `stderr_file`. Elsewhere: CreatePipe + CreateProcess with redirected handles.
class PipeChild {
 public:
  PipeChild() = default;
  ~PipeChild();  // kills and reaps the child
  PipeChild(const PipeChild&) = delete;
  PipeChild& operator=(const PipeChild&) = delete;

  // False with `error` set when the program cannot be started.
  bool start(const std::vector<std::string>& argv, const ChildLimits& limits, const std::filesystem::path& stderr_file,
             std::string& error, const std::vector<int>& inherit = {});
  enum class Io { Ok, Closed, TimedOut };
  // Writes `request` and reads exactly `reply_size` bytes back (both at once: a batch of many requests
  // and their replies), waiting at most `seconds` in all.
  Io call(const void* request, std::size_t request_size, void* reply, std::size_t reply_size, double seconds);
  // Kills the child (if still running) and says how it ended.
  ChildOutcome finish();

 private:
  int pid_ = -1;
  int to_child_ = -1;
  int from_child_ = -1;
  double started_ = 0.0;
  bool finished_ = false;
  ChildOutcome outcome_;
};

// Confines the calling process to computing: from now on it may read and write the descriptors it
// has, allocate memory and exit; any other system call (open a file, start a program, a socket...)
// kills it with SIGSYS. Returns false with `error` if the kernel refuses. Linux: a seccomp filter
// through libseccomp. Elsewhere: macOS sandbox_init (deprecated) or Windows AppContainer tokens;
// without it the process limits still hold. `rendering`: a GL exercise's host, whose OpenGL context
// (Mesa's llvmpipe, made before, with no threads of its own: LP_NUM_THREADS=0) also asks the system's
// memory size (sysinfo) and reads a link (readlink) when it compiles a shader.
bool confine_to_computing(std::string& error, bool rendering = false);

// "SIGSEGV (segmentation fault)".
std::string describe_signal(int signal);

// Whether a child was stopped by its CPU-time limit: SIGXCPU, or SIGKILL once past `cpu_limit_seconds`
// (the hard limit, 5 s after the soft one). Elsewhere: false.
bool stopped_at_cpu_limit(const ChildOutcome& o, double cpu_limit_seconds);

// From now on this process dies (SIGKILL) when its parent does: a task started by GNU parallel or a
// Slurm script leaves nothing behind when they are killed. Linux: PR_SET_PDEATHSIG; elsewhere a no-op
// (the parent's process-group or job-object kill covers it).
void die_with_parent();

// Lowers this process's own address-space limit (soft only, so that a child can still be given its
// own) to `bytes`, unless it is lower already. Linux: setrlimit(RLIMIT_AS); elsewhere nothing.
void limit_own_address_space(std::uint64_t bytes);

// The running executable (Linux: /proc/self/exe; macOS: _NSGetExecutablePath; Windows: GetModuleFileName).
std::filesystem::path self_executable();

// The address of `symbol` in a shared library loaded into this process for good (never unloaded: what
// is taken from it may be held anywhere): a student's GL exercise in the window, on their own machine
// (grading/live_cpp.h). Null with `error` set when it cannot be loaded or has no such symbol. Linux:
// dlopen (RTLD_NOW | RTLD_LOCAL) and dlsym; elsewhere LoadLibraryW and GetProcAddress on Windows, dlopen
// on macOS, not built here: the fallback says it needs Linux.
void* load_library_symbol(const std::filesystem::path& library, const char* symbol, std::string& error);

// A new, empty folder only we can read, under the system's temporary folder (mkdtemp).
std::filesystem::path make_private_temp_dir(const std::string& prefix);

// Empty where this build can grade submissions (Linux); elsewhere the one sentence saying what grading
// needs, which `shadowlab grade` and `check --submission` print before they do anything.
const std::string& grading_unavailable();

}  // namespace shadowlab::platform
