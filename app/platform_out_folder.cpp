// app/out_folder.h on POSIX systems (openat, mkdirat, renameat, unlinkat, fdopendir with O_NOFOLLOW),
// and by path elsewhere (grading needs Linux; the Windows build only compiles it).
#include "app/out_folder.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#if !defined(_WIN32)
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include "app/grade_report.h"  // report_text: a planted name shown escaped
#include "core/image_io.h"   // write_text_atomic (the by-path branch)

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

void check_name(const fs::path& folder, const std::string& name) {
  if (name.empty() || name == "." || name == ".." || name.find_first_of(std::string("/\\") + '\0') != std::string::npos)
    throw std::runtime_error((folder / report_text(name)).string() + ": not a name for a file in the output folder");
}

}  // namespace

OutFolder::OutFolder(OutFolder&& other) noexcept : path_(std::move(other.path_)), fd_(other.fd_) { other.fd_ = -1; }

OutFolder& OutFolder::operator=(OutFolder&& other) noexcept {
  std::swap(path_, other.path_);
  std::swap(fd_, other.fd_);
  return *this;
}

std::optional<std::string> OutFolder::read(const std::string& name, std::uint64_t max_bytes) const {
  return read_file(name, max_bytes, false);
}

std::string OutFolder::read_tail(const std::string& name, std::uint64_t max_bytes) const {
  return read_file(name, max_bytes, true).value_or("");
}

#if !defined(_WIN32)

namespace {

[[noreturn]] void fail_at(const fs::path& path, const char* what) {
  throw std::runtime_error(path.string() + ": " + what + ": " + std::strerror(errno));
}

// Removes `name` inside the folder `dir`: a folder with everything in it, anything else (a link
// itself) unlinked; never follows a link. False when something could not be removed.
bool remove_at(int dir, const char* name) {
  struct stat st {};
  if (::fstatat(dir, name, &st, AT_SYMLINK_NOFOLLOW) != 0) return errno == ENOENT;
  if (!S_ISDIR(st.st_mode)) return ::unlinkat(dir, name, 0) == 0 || errno == ENOENT;
  const int fd = ::openat(dir, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  DIR* entries = fd >= 0 ? ::fdopendir(fd) : nullptr;
  if (!entries) {
    if (fd >= 0) ::close(fd);
    return false;
  }
  bool ok = true;
  while (const dirent* e = ::readdir(entries))
    if (std::strcmp(e->d_name, ".") != 0 && std::strcmp(e->d_name, "..") != 0) ok = remove_at(::dirfd(entries), e->d_name) && ok;
  ::closedir(entries);
  return ::unlinkat(dir, name, AT_REMOVEDIR) == 0 && ok;
}

bool write_all(int fd, std::string_view bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

OutFolder::OutFolder(const fs::path& dir) : path_(dir), fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
  if (fd_ < 0) fail_at(dir, "cannot open the output folder");
}

OutFolder::~OutFolder() {
  if (fd_ >= 0) ::close(fd_);
}

OutFolder OutFolder::folder(const std::string& name, unsigned mode) const {
  check_name(path_, name);
  for (int attempt = 0; attempt < 4; ++attempt) {
    const int fd = ::openat(fd_, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) return OutFolder(path_ / name, fd);
    if (errno == ELOOP || errno == ENOTDIR) remove_at(fd_, name.c_str());  // a planted link or file: replaced
    else if (errno != ENOENT) break;
    if (::mkdirat(fd_, name.c_str(), static_cast<mode_t>(mode)) != 0 && errno != EEXIST) break;
  }
  fail_at(path_ / name, "cannot make the folder");
}

std::optional<OutFolder> OutFolder::existing_folder(const std::string& name) const {
  check_name(path_, name);
  const int fd = ::openat(fd_, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  return OutFolder(path_ / name, fd);
}

void OutFolder::write(const std::string& name, std::string_view text) const {
  check_name(path_, name);
  static std::atomic<unsigned> counter{0};
  const std::string tmp = "." + name + "." + std::to_string(::getpid()) + "." + std::to_string(counter++) + ".tmp";
  const int fd = ::openat(fd_, tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) fail_at(path_ / name, "cannot write");
  bool ok = write_all(fd, text);
  ok = ::close(fd) == 0 && ok;
  // A rename replaces a file or a link; a folder planted in the file's place is removed first.
  if (ok && ::renameat(fd_, tmp.c_str(), fd_, name.c_str()) != 0)
    ok = (errno == EISDIR || errno == ENOTEMPTY || errno == EEXIST) && remove_at(fd_, name.c_str()) &&
         ::renameat(fd_, tmp.c_str(), fd_, name.c_str()) == 0;
  if (!ok) {
    const int e = errno;
    ::unlinkat(fd_, tmp.c_str(), 0);
    errno = e;
    fail_at(path_ / name, "cannot write");
  }
}

void OutFolder::fresh_file(const std::string& name) const {
  check_name(path_, name);
  remove_at(fd_, name.c_str());
  const int fd = ::openat(fd_, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) fail_at(path_ / name, "cannot create");
  ::close(fd);
}

bool OutFolder::remove(const std::string& name) const {
  check_name(path_, name);
  return remove_at(fd_, name.c_str());
}

std::optional<std::string> OutFolder::read_file(const std::string& name, std::uint64_t max_bytes, bool tail) const {
  check_name(path_, name);
  struct stat st {};
  // Checked before it is opened (a device is never opened), and again on the handle.
  if (::fstatat(fd_, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  const int fd = ::openat(fd_, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::optional<std::string> text;
  const auto size = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) ? static_cast<std::uint64_t>(st.st_size) : ~0ull;
  if (size != ~0ull && (tail || size <= max_bytes)) {
    const std::uint64_t from = size > max_bytes ? size - max_bytes : 0;
    std::string bytes(static_cast<std::size_t>(size - from), '\0');
    std::size_t got = 0;
    while (got < bytes.size()) {
      const ssize_t n = ::pread(fd, bytes.data() + got, bytes.size() - got, static_cast<off_t>(from + got));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    bytes.resize(got);
    text = std::move(bytes);
  }
  ::close(fd);
  return text;
}

std::vector<std::string> OutFolder::names(bool folders_only) const {
  std::vector<std::string> out;
  const int fd = ::openat(fd_, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);  // its own position in the listing
  DIR* entries = fd >= 0 ? ::fdopendir(fd) : nullptr;
  if (!entries) {
    if (fd >= 0) ::close(fd);
    fail_at(path_, "cannot list the folder");
  }
  while (const dirent* e = ::readdir(entries)) {
    if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
    struct stat st {};
    if (folders_only && (::fstatat(fd_, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0 || !S_ISDIR(st.st_mode))) continue;
    out.emplace_back(e->d_name);
  }
  ::closedir(entries);
  std::sort(out.begin(), out.end());
  return out;
}

#else  // by path: the same refusals, without the handles (a link swapped between check and use is not caught)

OutFolder::OutFolder(const fs::path& dir) : path_(dir) {
  if (!fs::is_directory(dir)) throw std::runtime_error(dir.string() + ": cannot open the output folder");
}

OutFolder::~OutFolder() = default;

OutFolder OutFolder::folder(const std::string& name, unsigned) const {
  check_name(path_, name);
  const fs::path p = path_ / name;
  std::error_code ec;
  if (fs::is_symlink(p, ec) || (fs::exists(p, ec) && !fs::is_directory(p, ec))) fs::remove(p, ec);
  fs::create_directory(p, ec);
  if (!fs::is_directory(fs::symlink_status(p, ec))) throw std::runtime_error(p.string() + ": cannot make the folder");
  return OutFolder(p, -1);
}

std::optional<OutFolder> OutFolder::existing_folder(const std::string& name) const {
  check_name(path_, name);
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(path_ / name, ec))) return std::nullopt;
  return OutFolder(path_ / name, -1);
}

void OutFolder::write(const std::string& name, std::string_view text) const {
  check_name(path_, name);
  remove(name);
  write_text_atomic(path_ / name, std::string(text));
}

void OutFolder::fresh_file(const std::string& name) const { write(name, ""); }

bool OutFolder::remove(const std::string& name) const {
  check_name(path_, name);
  std::error_code ec;
  fs::remove_all(path_ / name, ec);  // a link itself, not what it points to
  return !ec;
}

std::optional<std::string> OutFolder::read_file(const std::string& name, std::uint64_t max_bytes, bool tail) const {
  check_name(path_, name);
  std::error_code ec;
  const fs::path p = path_ / name;
  if (!fs::is_regular_file(fs::symlink_status(p, ec))) return std::nullopt;
  const std::uint64_t size = fs::file_size(p, ec);
  if (ec || (!tail && size > max_bytes)) return std::nullopt;
  std::ifstream in(p, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(size > max_bytes ? size - max_bytes : 0));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> OutFolder::names(bool folders_only) const {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(path_, ec))
    if (!folders_only || fs::is_directory(e.symlink_status(ec))) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

#endif

}  // namespace shadowlab
