// Linux implementation of grading/sandbox.h: bubblewrap's command line and a libseccomp filter handed to
// it as a BPF program in a memory file. Elsewhere the fallback at the end refuses.
#include "grading/sandbox.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "grading/platform_process.h"

#if defined(__linux__)
#include <seccomp.h>
#include <sys/mman.h>
#include <unistd.h>

namespace shadowlab::platform {

namespace fs = std::filesystem;

namespace {

// The user the program runs as inside (nobody), mapped by bubblewrap's user namespace to ours.
constexpr const char* kSandboxUser = "65534";

using FilterPtr = std::unique_ptr<void, void (*)(scmp_filter_ctx)>;

void add_rules(scmp_filter_ctx ctx, uint32_t action, const std::vector<int>& calls) {
  for (int call : calls)
    if (const int rc = ::seccomp_rule_add(ctx, action, call, 0); rc != 0)
      throw std::runtime_error(std::string("seccomp: cannot add a rule: ") + std::strerror(-rc));
}

// A program that only computes: what a static C++ program's start-up and exit need (bubblewrap's own
// execve of it included), memory, time, the descriptors it was given, signals to itself.
FilterPtr computing_filter() {
  FilterPtr ctx(::seccomp_init(SCMP_ACT_KILL_PROCESS), ::seccomp_release);
  if (!ctx) throw std::runtime_error("seccomp_init failed");
  add_rules(ctx.get(), SCMP_ACT_ALLOW,
            {SCMP_SYS(execve), SCMP_SYS(arch_prctl), SCMP_SYS(set_tid_address), SCMP_SYS(set_robust_list),
             SCMP_SYS(rseq), SCMP_SYS(prlimit64), SCMP_SYS(getrandom), SCMP_SYS(uname), SCMP_SYS(readlink),
             SCMP_SYS(read), SCMP_SYS(write), SCMP_SYS(readv), SCMP_SYS(writev), SCMP_SYS(recvfrom),
             SCMP_SYS(sendto), SCMP_SYS(close), SCMP_SYS(dup), SCMP_SYS(dup2), SCMP_SYS(fstat),
             SCMP_SYS(newfstatat), SCMP_SYS(lseek), SCMP_SYS(brk), SCMP_SYS(mmap), SCMP_SYS(munmap),
             SCMP_SYS(mremap), SCMP_SYS(madvise), SCMP_SYS(mprotect), SCMP_SYS(futex), SCMP_SYS(clock_gettime),
             SCMP_SYS(gettimeofday), SCMP_SYS(clock_nanosleep), SCMP_SYS(nanosleep), SCMP_SYS(sched_yield),
             SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigaction), SCMP_SYS(rt_sigreturn), SCMP_SYS(sigaltstack),
             SCMP_SYS(getpid), SCMP_SYS(gettid), SCMP_SYS(tgkill), SCMP_SYS(exit), SCMP_SYS(exit_group)});
  // bubblewrap's reaper (PID 1 of the namespace) runs under the filter too: it waits for the program.
  add_rules(ctx.get(), SCMP_ACT_ALLOW, {SCMP_SYS(wait4)});
  // The grader's own second filter (grading/cpp_exercise_host.cpp) narrows this further once the host runs.
  add_rules(ctx.get(), SCMP_ACT_ALLOW, {SCMP_SYS(seccomp), SCMP_SYS(prctl)});
  return ctx;
}

// A compiler, linker or binutils reading hostile text: they open files and start each other inside
// the sandbox; what could reach beyond it (sockets, tracing, mounting, namespaces, kernel keys and
// modules, BPF) kills them.
FilterPtr toolchain_filter() {
  FilterPtr ctx(::seccomp_init(SCMP_ACT_ALLOW), ::seccomp_release);
  if (!ctx) throw std::runtime_error("seccomp_init failed");
  add_rules(ctx.get(), SCMP_ACT_KILL_PROCESS,
            {SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(connect), SCMP_SYS(bind), SCMP_SYS(listen),
             SCMP_SYS(ptrace), SCMP_SYS(process_vm_readv), SCMP_SYS(process_vm_writev), SCMP_SYS(mount),
             SCMP_SYS(umount2), SCMP_SYS(pivot_root), SCMP_SYS(chroot), SCMP_SYS(unshare), SCMP_SYS(setns),
             SCMP_SYS(keyctl), SCMP_SYS(add_key), SCMP_SYS(request_key), SCMP_SYS(bpf),
             SCMP_SYS(perf_event_open), SCMP_SYS(userfaultfd), SCMP_SYS(kexec_load), SCMP_SYS(kexec_file_load),
             SCMP_SYS(init_module), SCMP_SYS(finit_module), SCMP_SYS(delete_module), SCMP_SYS(reboot),
             SCMP_SYS(swapon), SCMP_SYS(swapoff), SCMP_SYS(acct), SCMP_SYS(open_by_handle_at),
             SCMP_SYS(name_to_handle_at), SCMP_SYS(iopl), SCMP_SYS(ioperm), SCMP_SYS(syslog),
             SCMP_SYS(pidfd_getfd), SCMP_SYS(pidfd_open)});
  return ctx;
}

// The filter as a BPF program in a memory file, for bubblewrap's --seccomp.
int export_filter(SyscallFilter which) {
  const FilterPtr ctx = which == SyscallFilter::Computing ? computing_filter() : toolchain_filter();
  if (const int rc = ::seccomp_attr_set(ctx.get(), SCMP_FLTATR_ACT_BADARCH, SCMP_ACT_KILL_PROCESS); rc != 0)
    throw std::runtime_error(std::string("seccomp: ") + std::strerror(-rc));
  const int fd = ::memfd_create("shadowlab-seccomp", MFD_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::string("memfd_create: ") + std::strerror(errno));
  if (const int rc = ::seccomp_export_bpf(ctx.get(), fd); rc != 0 || ::lseek(fd, 0, SEEK_SET) != 0) {
    ::close(fd);
    throw std::runtime_error(std::string("seccomp: cannot export the filter: ") + std::strerror(rc ? -rc : errno));
  }
  return fd;
}

// The system's folders as the host has them: /usr read-only, /bin, /lib... as links into it (merged
// /usr, Debian 12) or read-only binds.
void add_system(std::vector<std::string>& a, std::uint64_t tmp_bytes) {
  a.insert(a.end(), {"--ro-bind", "/usr", "/usr"});
  for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
    std::error_code ec;
    if (fs::is_symlink(top, ec)) a.insert(a.end(), {"--symlink", fs::read_symlink(top, ec).string(), top});
    else if (fs::is_directory(top, ec)) a.insert(a.end(), {"--ro-bind", top, top});
  }
  a.insert(a.end(), {"--dev", "/dev", "--size", std::to_string(tmp_bytes), "--tmpfs", "/tmp", "--setenv", "TMPDIR", "/tmp"});
}

}  // namespace

SandboxCommand::SandboxCommand(const SandboxSpec& spec, const std::vector<std::string>& argv) {
  filter_fd_ = export_filter(spec.filter);
  // Every namespace (mount, PID, network, IPC, UTS, cgroup, user) new; the program is `nobody` with no
  // capabilities, cannot make namespaces of its own, has no terminal to inject into, dies with us, and
  // starts with an empty environment.
  argv_ = {"bwrap", "--unshare-all", "--unshare-user", "--disable-userns", "--uid", kSandboxUser, "--gid",
           kSandboxUser, "--die-with-parent", "--new-session", "--cap-drop", "ALL", "--clearenv",
           "--setenv", "PATH", "/usr/bin:/bin", "--setenv", "LC_ALL", "C"};
  for (const auto& [name, value] : spec.env) argv_.insert(argv_.end(), {"--setenv", name, value});
  if (spec.system_toolchain) add_system(argv_, spec.tmp_bytes);
  for (const auto& m : spec.mounts)
    argv_.insert(argv_.end(), {m.writable ? "--bind" : "--ro-bind", m.host.string(), m.inside});
  // The root bubblewrap made (a tmpfs holding the mount points) read-only once everything is mounted.
  argv_.insert(argv_.end(), {"--remount-ro", "/", "--chdir", spec.chdir, "--seccomp", std::to_string(filter_fd_), "--"});
  argv_.insert(argv_.end(), argv.begin(), argv.end());
}

SandboxCommand::~SandboxCommand() {
  if (filter_fd_ >= 0) ::close(filter_fd_);
}

ChildOutcome inner_outcome(ChildOutcome o) {
  if (o.kind == ChildOutcome::Kind::Exited && o.exit_code > 128 && o.exit_code < 128 + 65) {
    o.kind = ChildOutcome::Kind::Signalled;
    o.signal = o.exit_code - 128;
    o.signal_name = describe_signal(o.signal);
    o.exit_code = 0;
  }
  return o;
}

const std::string& sandbox_unavailable() {
  static const std::string reason = [] {
    const fs::path dir = make_private_temp_dir("shadowlab-sandbox-probe");
    const fs::path log = dir / "probe.log";
    std::string why;
    try {
      SandboxSpec spec;
      spec.system_toolchain = true;
      spec.filter = SyscallFilter::Toolchain;
      const SandboxCommand probe(spec, {"/usr/bin/true"});
      const ChildOutcome o = run_child(probe.argv(), {10.0, 0, 0.0, 0}, log, {}, probe.inherited());
      std::ifstream in(log);
      std::string said;
      std::getline(in, said);
      if (o.kind == ChildOutcome::Kind::NotStarted)
        why = "bubblewrap (bwrap) is not installed (" + o.error + "); scripts/setup installs it (Debian: apt install bubblewrap)";
      else if (o.kind != ChildOutcome::Kind::Exited || o.exit_code != 0)
        why = "bubblewrap cannot make its sandbox here (" + (said.empty() ? "exit " + std::to_string(o.exit_code) : said) +
              "): it needs user and mount namespaces (a kernel that allows unprivileged user namespaces, or root)";
    } catch (const std::exception& e) {
      why = std::string("the sandbox's syscall filter cannot be made: ") + e.what();
    }
    std::error_code ec;
    fs::remove_all(dir, ec);
    return why;
  }();
  return reason;
}

}  // namespace shadowlab::platform

#else  // not Linux

namespace shadowlab::platform {

SandboxCommand::SandboxCommand(const SandboxSpec&, const std::vector<std::string>&) {
  throw std::runtime_error(sandbox_unavailable());
}
SandboxCommand::~SandboxCommand() = default;

ChildOutcome inner_outcome(ChildOutcome o) { return o; }

const std::string& sandbox_unavailable() {
  static const std::string reason =
      "grading C++ exercises runs them in a Linux sandbox (bubblewrap): use Linux or WSL";
  return reason;
}

}  // namespace shadowlab::platform

#endif
