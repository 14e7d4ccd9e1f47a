// The one file with operating-system calls (see platform.h).
#include "core/platform.h"

#include <cstring>
#include <deque>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#if (defined(__unix__) || defined(__APPLE__)) && !defined(SHADOWLAB_PORTABLE_PLATFORM)
#define SHADOWLAB_POSIX 1
#include <cerrno>
#include <map>
#include <mutex>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#else
#define SHADOWLAB_POSIX 0
#include <cstdio>
#include <fstream>
#include <sstream>
#endif

#include <cstdlib>
#if defined(_WIN32)
#include <io.h>  // _isatty, _fileno
#ifndef NOMINMAX
#define NOMINMAX
#endif
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#endif
#include <windows.h>  // LockFileEx
#else
#include <unistd.h>  // isatty
#endif

namespace shadowlab::platform {

namespace fs = std::filesystem;

namespace {

std::string too_large(std::uint64_t size, std::uint64_t max_bytes) {
  return "is " + std::to_string(size) + " bytes, above the limit of " + std::to_string(max_bytes) + " bytes";
}

int process_id();

// A name for a temporary file beside `name`: hidden, unique per process (its id) and per call (64
// random bits from a generator of each thread's own).
std::string temporary_name(const std::string& name) {
  thread_local std::mt19937_64 random{std::random_device{}()};
  const std::uint64_t r = random();
  char hex[17];
  for (int i = 0; i < 16; ++i) hex[i] = "0123456789abcdef"[(r >> (4 * i)) & 15u];
  hex[16] = 0;
  return "." + name + ".tmp-" + std::to_string(process_id()) + "-" + hex;
}

}  // namespace

#if SHADOWLAB_POSIX

namespace {

int process_id() { return static_cast<int>(::getpid()); }

// '/'-separated components, empty ones and '.' dropped.
std::deque<std::string> components(std::string_view path) {
  std::deque<std::string> out;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string_view part = path.substr(start, end - start);
    if (!part.empty() && part != ".") out.emplace_back(part);
    start = end + 1;
  }
  return out;
}

std::string errno_text(int e) { return std::strerror(e); }

FileProblem problem_of(int e) {
  switch (e) {
    case ENOENT:
    case ENOTDIR: return FileProblem::NotFound;
    case EACCES:
    case EPERM: return FileProblem::Denied;
    default: return FileProblem::Io;
  }
}

[[noreturn]] void fail_errno(int e, const std::string& what = "") {
  throw FileError(problem_of(e), (what.empty() ? "" : what + ": ") + errno_text(e));
}

class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(Fd&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}
  Fd& operator=(Fd&& o) noexcept {
    if (this != &o) {
      reset();
      fd_ = std::exchange(o.fd_, -1);
    }
    return *this;
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
}

void require_regular(mode_t mode) {
  if (!S_ISREG(mode)) {
    const std::string kind = kind_of(mode);
    throw FileError(FileProblem::NotRegular, kind == "not a regular file" ? kind : "is " + kind + ", not a regular file");
  }
}

// Reads an open regular file whole (its size checked again on the descriptor: what was opened is
// what is measured and read). The descriptor was opened non-blocking; reading a regular file is the
// same either way.
std::string read_open_file(int fd, std::uint64_t max_bytes) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) fail_errno(errno);
  require_regular(st.st_mode);
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > max_bytes) throw FileError(FileProblem::TooLarge, too_large(size, max_bytes));
  std::string bytes(static_cast<std::size_t>(size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_errno(errno, "read failed");
    if (n == 0) break;  // the file shrank meanwhile: what is there
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

Fd open_folder(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail_errno(errno);
  return Fd(fd);
}

void write_all(int fd, std::string_view bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_errno(errno, "write failed");
    done += static_cast<std::size_t>(n);
  }
}

// Creates a new file in `dir` with a unique temporary name beside `name`, exclusively.
std::pair<Fd, std::string> create_temporary(int dir, const std::string& name) {
  for (int attempt = 0;; ++attempt) {
    std::string tmp = temporary_name(name);
    const int fd = ::openat(dir, tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return {Fd(fd), std::move(tmp)};
    if (errno != EEXIST || attempt >= 16) fail_errno(errno, "cannot create a temporary file");
  }
}

}  // namespace

std::string read_regular_file(const fs::path& path, std::uint64_t max_bytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail_errno(errno);
  require_regular(st.st_mode);  // before opening: opening a device can have effects, a FIFO blocks
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) fail_errno(errno);
  const Fd file(fd);
  return read_open_file(file.get(), max_bytes);
}

struct Folder::State {
  Fd root;
};

Folder::Folder(const fs::path& dir) : state_(std::make_unique<State>()) { state_->root = open_folder(dir); }
Folder::~Folder() = default;
Folder::Folder(Folder&&) noexcept = default;

std::string Folder::read(std::string_view relative, std::uint64_t max_bytes) const {
  if (relative.empty()) throw FileError(FileProblem::NotFound, "an empty path names no file");
  if (relative.find('\0') != std::string_view::npos) throw FileError(FileProblem::NotFound, "the path holds a NUL");
  if (relative.front() == '/') throw FileError(FileProblem::Outside, "an absolute path leads outside the folder");
  std::deque<std::string> pending = components(relative);
  if (pending.empty()) throw FileError(FileProblem::NotRegular, "names the folder itself, not a file");
  // The folders walked through, as open handles; the first is the model's folder.
  std::vector<Fd> walked;
  walked.emplace_back(::dup(state_->root.get()));
  if (walked.back().get() < 0) fail_errno(errno);
  int links = 0, retries = 0;
  while (!pending.empty()) {
    const std::string name = std::move(pending.front());
    pending.pop_front();
    if (name == "..") {
      if (walked.size() == 1) throw FileError(FileProblem::Outside, "'..' leads outside the folder");
      walked.pop_back();
      continue;
    }
    const int at = walked.back().get();
    const bool last = pending.empty();
    // Look before opening: a device or a FIFO is refused unopened. The open below is what counts.
    struct stat st {};
    if (::fstatat(at, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) fail_errno(errno);
    if (!S_ISLNK(st.st_mode)) {
      if (!last && !S_ISDIR(st.st_mode)) throw FileError(FileProblem::NotFound, "'" + name + "' is not a folder");
      if (last) require_regular(st.st_mode);
      const int flags = O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY | O_NONBLOCK | (last ? 0 : O_DIRECTORY);
      const int fd = ::openat(at, name.c_str(), flags);
      if (fd >= 0) {
        Fd opened(fd);
        if (!last) {
          walked.push_back(std::move(opened));
          continue;
        }
        if (max_bytes == 0) {
          struct stat file {};
          if (::fstat(opened.get(), &file) != 0) fail_errno(errno);
          require_regular(file.st_mode);
          return {};
        }
        return read_open_file(opened.get(), max_bytes);
      }
      // ELOOP/ENOTDIR: it became a link (or something else) after fstatat: look again.
      if ((errno != ELOOP && errno != ENOTDIR) || ++retries > 64) fail_errno(errno);
      pending.push_front(name);
      continue;
    }
    // A symbolic link: resolved by hand, its target's components taking its place.
    if (++links > 40) throw FileError(FileProblem::Io, "too many symbolic links");
    std::vector<char> target(4096);
    const ssize_t n = ::readlinkat(at, name.c_str(), target.data(), target.size());
    if (n < 0) {
      if (errno != EINVAL || ++retries > 64) fail_errno(errno);  // EINVAL: no longer a link; look again
      pending.push_front(name);
      continue;
    }
    if (static_cast<std::size_t>(n) >= target.size()) throw FileError(FileProblem::Io, "a symbolic link is too long");
    const std::string_view link(target.data(), static_cast<std::size_t>(n));
    if (link.empty() || link.front() == '/')
      throw FileError(FileProblem::Outside, "'" + name + "' is a symbolic link to an absolute path, outside the folder");
    std::deque<std::string> inner = components(link);
    pending.insert(pending.begin(), inner.begin(), inner.end());
  }
  throw FileError(FileProblem::NotRegular, "names a folder, not a file");
}

void write_file_atomic(const fs::path& target, std::string_view bytes, bool durable,
                       const std::function<void()>& before_rename) {
  const fs::path folder = target.parent_path();
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == "..") throw FileError(FileProblem::NotRegular, "names a folder, not a file");
  const Fd dir = open_folder(folder);
  auto [file, tmp] = create_temporary(dir.get(), name);
  try {
    write_all(file.get(), bytes);
    if (durable && ::fsync(file.get()) != 0) fail_errno(errno, "fsync failed");
    if (::close(file.release()) != 0) fail_errno(errno, "close failed");
    if (before_rename) before_rename();
    if (::renameat(dir.get(), tmp.c_str(), dir.get(), name.c_str()) != 0) fail_errno(errno, "cannot replace it");
  } catch (...) {
    ::unlinkat(dir.get(), tmp.c_str(), 0);
    throw;
  }
  if (durable) ::fsync(dir.get());  // the rename itself; best effort (some file systems refuse)
}

bool write_new_file(const fs::path& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) {
    if (errno == EEXIST) return false;
    fail_errno(errno);
  }
  Fd file(fd);
  try {
    write_all(file.get(), bytes);
    if (::close(file.release()) != 0) fail_errno(errno, "close failed");
  } catch (...) {
    ::unlink(path.c_str());
    throw;
  }
  return true;
}

void probe_writable(const fs::path& dir) {
  const Fd folder = open_folder(dir);
  auto [probe, name] = create_temporary(folder.get(), "shadowlab-write-test");
  probe.reset();
  ::unlinkat(folder.get(), name.c_str(), 0);
}

bool lock_folder(const fs::path& dir, std::string* holder) {
  // Locks held by this process, by folder identity: flock conflicts between two descriptors of one
  // process too, and a process may name one folder twice.
  static std::mutex mutex;
  static std::map<std::pair<dev_t, ino_t>, int> held;
  const std::lock_guard guard(mutex);
  const Fd folder = open_folder(dir);
  struct stat st {};
  if (::fstat(folder.get(), &st) != 0) fail_errno(errno);
  if (held.contains({st.st_dev, st.st_ino})) return true;
  const int fd = ::openat(folder.get(), ".shadowlab.lock", O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) fail_errno(errno, "cannot create .shadowlab.lock");
  Fd lock(fd);
  struct stat ls {};
  if (::fstat(lock.get(), &ls) != 0) fail_errno(errno);
  require_regular(ls.st_mode);
  if (::flock(lock.get(), LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK) fail_errno(errno, "cannot lock .shadowlab.lock");
    if (holder) {
      char pid[32] = {};
      const ssize_t n = ::pread(lock.get(), pid, sizeof pid - 1, 0);
      *holder = n > 0 ? std::string(pid, static_cast<std::size_t>(n)) : "";
      while (!holder->empty() && (holder->back() == '\n' || holder->back() == ' ')) holder->pop_back();
      if (holder->find_first_not_of("0123456789") != std::string::npos) holder->clear();
    }
    return false;
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(lock.get(), 0) == 0) (void)!::pwrite(lock.get(), pid.data(), pid.size(), 0);
  held[{st.st_dev, st.st_ino}] = lock.release();  // kept open (and locked) until the process ends
  return true;
}

FileLock::FileLock(const fs::path& path) {
  Fd fd(::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666));
  if (fd.get() < 0) fail_errno(errno, "cannot open the lock file");
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) fail_errno(errno);
  require_regular(st.st_mode);
  while (::flock(fd.get(), LOCK_EX) != 0)
    if (errno != EINTR) fail_errno(errno, "cannot lock");
  handle_ = fd.release();
}

FileLock::~FileLock() {
  if (handle_ >= 0) ::close(static_cast<int>(handle_));  // closing the descriptor releases the lock
}

bool rename_no_replace(const fs::path& from, const fs::path& to) {
  // link() fails when `to` exists, where rename() would replace it; then the old name goes.
  if (::link(from.c_str(), to.c_str()) == 0) {
    if (::unlink(from.c_str()) != 0) fail_errno(errno, "cannot remove the old name");
    return true;
  }
  if (errno == EEXIST) return false;
  if (errno != EPERM && errno != ENOTSUP && errno != EOPNOTSUPP && errno != EXDEV) fail_errno(errno);
  // A file system without hard links: check, then rename (a race here can only lose to another rename).
  struct stat st {};
  if (::lstat(to.c_str(), &st) == 0) return false;
  if (::rename(from.c_str(), to.c_str()) != 0) fail_errno(errno);
  return true;
}

#else  // the portable fallback: the same refusals, by path

namespace {

int process_id() { return 0; }  // the random part alone keeps names apart

// Creates `path` for writing, failing if anything has that name (C11's "x"; MSVC's CRT has it too).
// On Windows the path goes as UTF-16, never through the ANSI code page.
std::FILE* open_new(const fs::path& path) {
#if defined(_WIN32)
  return _wfopen(path.c_str(), L"wbx");
#else
  return std::fopen(path.c_str(), "wbx");
#endif
}

[[noreturn]] void fail_ec(const std::error_code& ec) {
  throw FileError(ec == std::errc::no_such_file_or_directory ? FileProblem::NotFound
                  : ec == std::errc::permission_denied       ? FileProblem::Denied
                                                             : FileProblem::Io,
                  ec.message());
}

std::string read_by_path(const fs::path& path, std::uint64_t max_bytes) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec) fail_ec(ec);
  if (status.type() != fs::file_type::regular) throw FileError(FileProblem::NotRegular, "not a regular file");
  if (max_bytes == 0) return {};  // checked, not read (Folder::read)
  const std::uint64_t size = fs::file_size(path, ec);
  if (ec) fail_ec(ec);
  if (size > max_bytes) throw FileError(FileProblem::TooLarge, too_large(size, max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(FileProblem::Io, "cannot open it");
  std::ostringstream s;
  s << in.rdbuf();
  std::string bytes = s.str();
  if (bytes.size() > max_bytes) throw FileError(FileProblem::TooLarge, too_large(bytes.size(), max_bytes));
  return bytes;
}

}  // namespace

std::string read_regular_file(const fs::path& path, std::uint64_t max_bytes) { return read_by_path(path, max_bytes); }

struct Folder::State {
  fs::path canonical;
};

Folder::Folder(const fs::path& dir) : state_(std::make_unique<State>()) {
  std::error_code ec;
  state_->canonical = fs::canonical(dir.empty() ? fs::path(".") : dir, ec);
  if (ec) fail_ec(ec);
}
Folder::~Folder() = default;
Folder::Folder(Folder&&) noexcept = default;

std::string Folder::read(std::string_view relative, std::uint64_t max_bytes) const {
  if (relative.empty()) throw FileError(FileProblem::NotFound, "an empty path names no file");
  if (relative.find('\0') != std::string_view::npos) throw FileError(FileProblem::NotFound, "the path holds a NUL");
  const fs::path rel(std::string{relative});
  if (rel.has_root_path() || relative.front() == '/' || relative.front() == '\\')
    throw FileError(FileProblem::Outside, "an absolute path leads outside the folder");
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(state_->canonical / rel, ec);
  if (ec) fail_ec(ec);
  const auto [in_base, in_target] =
      std::mismatch(state_->canonical.begin(), state_->canonical.end(), target.begin(), target.end());
  if (in_base != state_->canonical.end() || in_target == target.end())
    throw FileError(FileProblem::Outside, "it leads outside the folder");
  return read_by_path(target, max_bytes);
}

void write_file_atomic(const fs::path& target, std::string_view bytes, bool,
                       const std::function<void()>& before_rename) {
  const std::string name = target.filename().string();
  if (name.empty() || name == "." || name == "..") throw FileError(FileProblem::NotRegular, "names a folder, not a file");
  const fs::path tmp = target.parent_path() / temporary_name(name);
  {
    std::FILE* f = open_new(tmp);
    if (!f) throw FileError(FileProblem::Io, "cannot create a temporary file");
    const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    if (std::fclose(f) != 0 || !ok) {
      std::error_code ignore;
      fs::remove(tmp, ignore);
      throw FileError(FileProblem::Io, "write failed");
    }
  }
  if (before_rename) before_rename();
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    std::error_code ignore;
    fs::remove(tmp, ignore);
    throw FileError(FileProblem::Io, "cannot replace it: " + ec.message());
  }
}

bool write_new_file(const fs::path& path, std::string_view bytes) {
  std::FILE* f = open_new(path);
  if (!f) {
    std::error_code ec;
    if (fs::exists(fs::symlink_status(path, ec))) return false;
    throw FileError(FileProblem::Io, "cannot create it");
  }
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !ok) throw FileError(FileProblem::Io, "write failed");
  return true;
}

void probe_writable(const fs::path& dir) {
  const fs::path probe = dir / temporary_name("shadowlab-write-test");
  if (!write_new_file(probe, "")) throw FileError(FileProblem::Io, "cannot create a file in it");
  std::error_code ec;
  fs::remove(probe, ec);
}

bool lock_folder(const fs::path&, std::string*) { return true; }

#if defined(_WIN32)
FileLock::FileLock(const fs::path& path) {
  const HANDLE h = ::CreateFileW(path.c_str(), GENERIC_READ | GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                                 nullptr, OPEN_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
  if (h == INVALID_HANDLE_VALUE) throw FileError(FileProblem::Io, "cannot open the lock file (error " + std::to_string(::GetLastError()) + ")");
  OVERLAPPED whole{};  // from offset 0, the largest range: the whole file, whatever its size
  if (!::LockFileEx(h, LOCKFILE_EXCLUSIVE_LOCK, 0, MAXDWORD, MAXDWORD, &whole)) {
    const DWORD e = ::GetLastError();
    ::CloseHandle(h);
    throw FileError(FileProblem::Io, "cannot lock (error " + std::to_string(e) + ")");
  }
  handle_ = reinterpret_cast<std::intptr_t>(h);
}

FileLock::~FileLock() {
  if (handle_ == -1) return;
  const HANDLE h = reinterpret_cast<HANDLE>(handle_);
  OVERLAPPED whole{};
  ::UnlockFileEx(h, 0, MAXDWORD, MAXDWORD, &whole);
  ::CloseHandle(h);
}
#else
FileLock::FileLock(const fs::path&) {}
FileLock::~FileLock() = default;
#endif

bool rename_no_replace(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(to, ec))) return false;
  fs::rename(from, to, ec);
  if (ec) fail_ec(ec);
  return true;
}

#endif

}  // namespace shadowlab::platform
