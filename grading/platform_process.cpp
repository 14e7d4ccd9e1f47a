// Linux implementation of grading/platform_process.h (POSIX with Linux's prctl, seccomp, pipe2 and
// /proc); on other systems the fallback at the end says that grading submissions needs Linux.
#include "grading/platform_process.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

#if defined(__linux__)
#include <dlfcn.h>
#include <fcntl.h>
#include <poll.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace shadowlab::platform {

namespace fs = std::filesystem;

namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// argv[0] without a slash is looked up in PATH here, before fork: the child only calls execve.
std::string resolve_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return name;  // execve fails and says so
}

// Everything the child needs, built before fork (after fork only async-signal-safe calls are made).
struct ExecPlan {
  std::string program;
  std::vector<std::string> args, env_strings;
  std::vector<char*> argv, envp;
  std::vector<int> inherit;  // descriptors the program keeps (their close-on-exec flag cleared in the child)

  ExecPlan(const std::vector<std::string>& a, const std::map<std::string, std::string>& env, std::vector<int> keep)
      : args(a), inherit(std::move(keep)) {
    program = resolve_program(args.at(0));
    std::map<std::string, std::string> merged;
    for (char** e = environ; e && *e; ++e) {
      const std::string entry = *e;
      const auto eq = entry.find('=');
      if (eq != std::string::npos) merged[entry.substr(0, eq)] = entry.substr(eq + 1);
    }
    // A library preloaded into this process (a sanitizer's runtime, as scripts/test runs test_gl) is not
    // preloaded into what it starts: bubblewrap, the compiler and a student's program run as anywhere else
    // (bubblewrap aborted under a preloaded AddressSanitizer runtime: CI of b520b6d).
    merged.erase("LD_PRELOAD");
    for (const auto& [k, v] : env) merged[k] = v;
    for (const auto& [k, v] : merged) env_strings.push_back(k + "=" + v);
    for (auto& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);
    for (auto& s : env_strings) envp.push_back(s.data());
    envp.push_back(nullptr);
  }
};

// In the child, after fork: own process group, die with the parent, limits, then exec. On failure the
// errno goes back through `report` (close-on-exec, so a successful exec closes it with nothing written).
[[noreturn]] void exec_child(const ExecPlan& plan, const ChildLimits& limits, pid_t parent, int report) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);  // the parent died before prctl
  struct rlimit no_core = {0, 0};
  ::setrlimit(RLIMIT_CORE, &no_core);  // a crashing student program writes no core file
  if (limits.address_space_bytes > 0) {
    struct rlimit as = {limits.address_space_bytes, limits.address_space_bytes};
    ::setrlimit(RLIMIT_AS, &as);
  }
  if (limits.cpu_seconds > 0) {
    const auto soft = static_cast<rlim_t>(limits.cpu_seconds + 0.999);
    struct rlimit cpu = {soft, soft + 5};
    ::setrlimit(RLIMIT_CPU, &cpu);
  }
  if (limits.file_size_bytes > 0) {
    struct rlimit fsize = {limits.file_size_bytes, limits.file_size_bytes};
    ::setrlimit(RLIMIT_FSIZE, &fsize);
  }
  for (int fd : plan.inherit) ::fcntl(fd, F_SETFD, 0);
  ::execve(plan.program.c_str(), plan.argv.data(), plan.envp.data());
  const int e = errno;
  [[maybe_unused]] auto n = ::write(report, &e, sizeof e);
  ::_exit(127);
}

// Starts the child; returns its pid, or -1 with `error` set.
pid_t spawn(const ExecPlan& plan, const ChildLimits& limits, int stdin_fd, int stdout_fd, int stderr_fd,
            std::string& error) {
  int report[2];
  if (::pipe2(report, O_CLOEXEC) != 0) {
    error = std::string("pipe: ") + std::strerror(errno);
    return -1;
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    error = std::string("fork: ") + std::strerror(errno);
    ::close(report[0]);
    ::close(report[1]);
    return -1;
  }
  if (pid == 0) {
    ::close(report[0]);
    if (stdin_fd >= 0) ::dup2(stdin_fd, 0);
    if (stdout_fd >= 0) ::dup2(stdout_fd, 1);
    if (stderr_fd >= 0) ::dup2(stderr_fd, 2);
    exec_child(plan, limits, parent, report[1]);
  }
  ::setpgid(pid, pid);  // also here: no race with a kill of the group before the child ran setpgid
  ::close(report[1]);
  int child_errno = 0;
  ssize_t got;
  do got = ::read(report[0], &child_errno, sizeof child_errno);
  while (got < 0 && errno == EINTR);
  ::close(report[0]);
  if (got == static_cast<ssize_t>(sizeof child_errno)) {
    error = plan.program + ": cannot run: " + std::strerror(child_errno);
    int status;
    ::waitpid(pid, &status, 0);
    return -1;
  }
  return pid;
}

// Waits for `pid` until `deadline` (0: forever); kills the group at the deadline. Fills `outcome`.
void wait_for(pid_t pid, double started, double deadline, ChildOutcome& outcome) {
  int status = 0;
  struct rusage usage = {};
  bool timed_out = false;
  int sleep_ms = 2;
  for (;;) {
    const pid_t r = ::wait4(pid, &status, deadline > 0 ? WNOHANG : 0, &usage);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) {
      outcome.kind = ChildOutcome::Kind::NotStarted;
      outcome.error = std::string("wait: ") + std::strerror(errno);
      return;
    }
    if (deadline > 0 && now_seconds() >= deadline) {
      timed_out = true;
      ::kill(-pid, SIGKILL);
      deadline = 0;  // now wait for it to go
      continue;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(sleep_ms));
    sleep_ms = std::min(sleep_ms * 2, 50);
  }
  ::kill(-pid, SIGKILL);  // anything it left behind in its group (a compiler's subprocesses)
  outcome.seconds = now_seconds() - started;
  outcome.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
  auto secs = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  outcome.cpu_seconds = secs(usage.ru_utime) + secs(usage.ru_stime);
  if (timed_out) {
    outcome.kind = ChildOutcome::Kind::TimedOut;
  } else if (WIFSIGNALED(status)) {
    outcome.kind = ChildOutcome::Kind::Signalled;
    outcome.signal = WTERMSIG(status);
    outcome.signal_name = describe_signal(outcome.signal);
  } else {
    outcome.kind = ChildOutcome::Kind::Exited;
    outcome.exit_code = WEXITSTATUS(status);
  }
}

}  // namespace

std::string describe_signal(int signal) {
  struct Name {
    int signal;
    const char* name;
    const char* meaning;
  };
  static const Name names[] = {
      {SIGSEGV, "SIGSEGV", "segmentation fault: a bad pointer or an index out of range"},
      {SIGABRT, "SIGABRT", "aborted: a failed assert or an uncaught exception"},
      {SIGFPE, "SIGFPE", "arithmetic error: an integer division by zero"},
      {SIGBUS, "SIGBUS", "bus error"},
      {SIGILL, "SIGILL", "illegal instruction"},
      {SIGKILL, "SIGKILL", "killed"},
      {SIGTERM, "SIGTERM", "terminated"},
      {SIGSYS, "SIGSYS", "a system call grading does not allow: the exercise may only compute"},
      {SIGXCPU, "SIGXCPU", "CPU time limit reached"},
      {SIGXFSZ, "SIGXFSZ", "file size limit reached: it wrote too much (its printed output counts)"},
  };
  for (const auto& n : names)
    if (n.signal == signal) return std::string(n.name) + " (" + n.meaning + ")";
  const char* text = ::strsignal(signal);
  return "signal " + std::to_string(signal) + (text ? std::string(" (") + text + ")" : "");
}

bool stopped_at_cpu_limit(const ChildOutcome& o, double cpu_limit_seconds) {
  return o.kind == ChildOutcome::Kind::Signalled &&
         (o.signal == SIGXCPU || (o.signal == SIGKILL && cpu_limit_seconds > 0 && o.cpu_seconds >= cpu_limit_seconds));
}

ChildOutcome run_child(const std::vector<std::string>& argv, const ChildLimits& limits, const fs::path& log_file,
                       const std::map<std::string, std::string>& env, const std::vector<int>& inherit) {
  ChildOutcome outcome;
  const ExecPlan plan(argv, env, inherit);
  const int log = log_file.empty() ? -1 : ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (!log_file.empty() && log < 0) {
    outcome.error = log_file.string() + ": cannot write the log: " + std::strerror(errno);
    return outcome;
  }
  const int null_in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const double started = now_seconds();
  const pid_t pid = spawn(plan, limits, null_in, log, log, outcome.error);
  if (log >= 0) ::close(log);
  if (null_in >= 0) ::close(null_in);
  if (pid < 0) return outcome;
  wait_for(pid, started, limits.wall_seconds > 0 ? started + limits.wall_seconds : 0.0, outcome);
  return outcome;
}

PipeChild::~PipeChild() { finish(); }

bool PipeChild::start(const std::vector<std::string>& argv, const ChildLimits& limits, const fs::path& stderr_file,
                      std::string& error, const std::vector<int>& inherit) {
  const ExecPlan plan(argv, {}, inherit);
  // One socket pair carries both directions; send() with MSG_NOSIGNAL means a child that died does not
  // kill us with SIGPIPE.
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
    error = std::string("socketpair: ") + std::strerror(errno);
    return false;
  }
  const int log = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0) {
    error = stderr_file.string() + ": cannot write: " + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  started_ = now_seconds();
  pid_ = spawn(plan, limits, fds[1], fds[1], log, error);
  ::close(fds[1]);
  ::close(log);
  if (pid_ < 0) {
    ::close(fds[0]);
    return false;
  }
  to_child_ = from_child_ = fds[0];
  finished_ = false;
  return true;
}

PipeChild::Io PipeChild::call(const void* request, std::size_t request_size, void* reply, std::size_t reply_size,
                              double seconds) {
  if (pid_ < 0 || finished_) return Io::Closed;
  const double deadline = now_seconds() + seconds;
  const auto* out = static_cast<const char*>(request);
  auto* in = static_cast<char*>(reply);
  std::size_t sent = 0, got = 0;
  // Sending and receiving interleaved: a batch of requests larger than the socket's buffers would
  // otherwise leave both sides waiting for the other to read.
  while (got < reply_size) {
    const int ms = static_cast<int>((deadline - now_seconds()) * 1000.0);
    if (ms <= 0) return Io::TimedOut;
    struct pollfd p = {to_child_, static_cast<short>(POLLIN | (sent < request_size ? POLLOUT : 0)), 0};
    const int r = ::poll(&p, 1, ms);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) return Io::Closed;
    if (r == 0) continue;
    if ((p.revents & POLLOUT) && sent < request_size) {
      const ssize_t n = ::send(to_child_, out + sent, request_size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n > 0) sent += static_cast<std::size_t>(n);
      else if (n < 0 && errno != EAGAIN && errno != EINTR) return Io::Closed;
    }
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
      const ssize_t n = ::recv(from_child_, in + got, reply_size - got, MSG_DONTWAIT);
      if (n > 0) got += static_cast<std::size_t>(n);
      else if (n == 0 || (errno != EAGAIN && errno != EINTR)) return Io::Closed;
    }
  }
  return Io::Ok;
}

ChildOutcome PipeChild::finish() {
  if (pid_ < 0 || finished_) return outcome_;
  finished_ = true;
  ::close(to_child_);  // a well-behaved child sees end of input and exits
  to_child_ = from_child_ = -1;
  // Give it a moment to exit on its own (so a crash is reported as the crash), then kill.
  wait_for(pid_, started_, now_seconds() + 1.0, outcome_);
  return outcome_;
}

bool confine_to_computing(std::string& error, bool rendering) {
  scmp_filter_ctx ctx = ::seccomp_init(SCMP_ACT_KILL_PROCESS);
  if (!ctx) {
    error = "seccomp_init failed";
    return false;
  }
  // Reading and writing the descriptors already open, memory, time, and leaving. fstat: stdio asks
  // before its first write. Signals only to itself (abort() raises SIGABRT through tgkill).
  const int allowed[] = {SCMP_SYS(read),         SCMP_SYS(write),        SCMP_SYS(readv),
                         SCMP_SYS(writev),       SCMP_SYS(recvfrom),     SCMP_SYS(sendto),
                         SCMP_SYS(brk),          SCMP_SYS(mmap),         SCMP_SYS(munmap),
                         SCMP_SYS(mremap),       SCMP_SYS(madvise),      SCMP_SYS(mprotect),
                         SCMP_SYS(fstat),        SCMP_SYS(newfstatat),   SCMP_SYS(lseek),
                         SCMP_SYS(futex),        SCMP_SYS(clock_gettime), SCMP_SYS(gettimeofday),
                         SCMP_SYS(clock_nanosleep), SCMP_SYS(nanosleep), SCMP_SYS(sched_yield),
                         SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigaction), SCMP_SYS(rt_sigreturn),
                         SCMP_SYS(getpid),       SCMP_SYS(gettid),       SCMP_SYS(exit),
                         SCMP_SYS(exit_group)};
  int rc = 0;
  for (int call : allowed) rc = rc ? rc : ::seccomp_rule_add(ctx, SCMP_ACT_ALLOW, call, 0);
  const pid_t self = ::getpid();
  if (rendering)
    for (int call : {SCMP_SYS(sysinfo), SCMP_SYS(readlink)}) rc = rc ? rc : ::seccomp_rule_add(ctx, SCMP_ACT_ALLOW, call, 0);
  if (!rc) rc = ::seccomp_rule_add(ctx, SCMP_ACT_ALLOW, SCMP_SYS(tgkill), 1, SCMP_A0(SCMP_CMP_EQ, static_cast<scmp_datum_t>(self)));
  if (!rc) rc = ::seccomp_load(ctx);
  ::seccomp_release(ctx);
  if (rc) {
    error = std::string("seccomp: ") + std::strerror(-rc);
    return false;
  }
  return true;
}

void die_with_parent() {
  const pid_t parent = ::getppid();
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::raise(SIGKILL);  // it died before prctl
}

void limit_own_address_space(std::uint64_t bytes) {
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) != 0) return;
  const auto wanted = static_cast<rlim_t>(bytes);
  if (limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= wanted) return;  // already lower
  limit.rlim_cur = limit.rlim_max == RLIM_INFINITY ? wanted : std::min(wanted, limit.rlim_max);
  ::setrlimit(RLIMIT_AS, &limit);
}

fs::path self_executable() { return fs::read_symlink("/proc/self/exe"); }

const std::string& grading_unavailable() {
  static const std::string available;
  return available;
}

void* load_library_symbol(const fs::path& library, const char* symbol, std::string& error) {
  void* handle = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = ::dlerror();
    error = why ? why : library.string() + ": cannot be loaded";
    return nullptr;
  }
  ::dlerror();
  void* address = ::dlsym(handle, symbol);
  if (!address) error = library.string() + ": no " + symbol;
  return address;
}

fs::path make_private_temp_dir(const std::string& prefix) {
  std::string pattern = (fs::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (!::mkdtemp(pattern.data()))
    throw std::runtime_error(pattern + ": cannot create a temporary folder: " + std::strerror(errno));
  return pattern;
}

}  // namespace shadowlab::platform

#else  // not Linux

#include <random>

namespace shadowlab::platform {

namespace fs = std::filesystem;

const std::string& grading_unavailable() {
  static const std::string reason =
      "grading submissions runs student code in confined processes, which needs Linux (a Linux machine, WSL "
      "on Windows, or a Linux cluster); this build is not for Linux";
  return reason;
}

namespace {
std::string needs_linux(const std::string& what) { return what + ": " + grading_unavailable(); }
}  // namespace

ChildOutcome run_child(const std::vector<std::string>& argv, const ChildLimits&, const fs::path&,
                       const std::map<std::string, std::string>&, const std::vector<int>&) {
  ChildOutcome outcome;
  outcome.error = needs_linux(argv.empty() ? "run" : argv.front());
  return outcome;
}

PipeChild::~PipeChild() = default;

bool PipeChild::start(const std::vector<std::string>& argv, const ChildLimits&, const fs::path&, std::string& error,
                      const std::vector<int>&) {
  error = needs_linux(argv.empty() ? "start" : argv.front());
  return false;
}

PipeChild::Io PipeChild::call(const void*, std::size_t, void*, std::size_t, double) { return Io::Closed; }

ChildOutcome PipeChild::finish() { return outcome_; }

bool confine_to_computing(std::string& error, bool) {
  error = needs_linux("confining a program to computing");
  return false;
}

std::string describe_signal(int signal) { return "signal " + std::to_string(signal); }

bool stopped_at_cpu_limit(const ChildOutcome&, double) { return false; }

void die_with_parent() {}

void limit_own_address_space(std::uint64_t) {}

fs::path self_executable() { throw std::runtime_error(needs_linux("shadowlab grade")); }

void* load_library_symbol(const fs::path&, const char* symbol, std::string& error) {
  error = needs_linux(std::string("loading ") + symbol);
  return nullptr;
}

fs::path make_private_temp_dir(const std::string& prefix) {
  std::random_device random;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path dir = fs::temp_directory_path() / (prefix + "-" + std::to_string(random()));
    if (fs::create_directory(dir)) {
      fs::permissions(dir, fs::perms::owner_all);
      return dir;
    }
  }
  throw std::runtime_error(prefix + ": cannot create a temporary folder in " + fs::temp_directory_path().string());
}

}  // namespace shadowlab::platform

#endif
