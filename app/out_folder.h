// The output folder of `shadowlab grade`, written without ever following a link planted in it. The
// implementation is the operating system's (app/platform_out_folder.cpp: POSIX *at calls).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab {

// A folder under --out the grader writes in, opened once: every file and folder inside it is made,
// replaced, read and removed relative to that handle (openat, mkdirat, renameat, unlinkat with
// O_NOFOLLOW), never through a link. A link, or a file, planted where the grader's own folder or file
// goes is removed and replaced, never followed: what it points to stays as it was. --out itself is
// opened as the user named it. Names are single components (no '/'). Elsewhere than POSIX (grading
// needs Linux) the same checks are made by path.
class OutFolder {
 public:
  OutFolder() = default;
  explicit OutFolder(const std::filesystem::path& dir);  // throws std::runtime_error naming it
  ~OutFolder();
  OutFolder(OutFolder&& other) noexcept;
  OutFolder& operator=(OutFolder&& other) noexcept;
  OutFolder(const OutFolder&) = delete;
  OutFolder& operator=(const OutFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The folder `name` inside, made (with `mode`) when missing; a link or a file there is replaced.
  OutFolder folder(const std::string& name, unsigned mode = 0755) const;
  // The real folder `name` inside, to read: nullopt when missing or anything else (a link).
  std::optional<OutFolder> existing_folder(const std::string& name) const;
  // Writes the file `name` atomically: a new temporary file (created exclusively), renamed over
  // whatever has the name (a link is replaced, not written through).
  void write(const std::string& name, std::string_view text) const;
  // An empty file `name` of our own, whatever was there removed first: for a program that opens it by
  // its path (a check's log, GNU parallel's job log).
  void fresh_file(const std::string& name) const;
  // Removes `name`: a file, a link (not what it points to), or a folder with everything inside; false
  // when something could not be removed.
  bool remove(const std::string& name) const;
  // The regular file `name` (not a link, a FIFO or a device): nullopt when there is none or it is
  // larger than max_bytes. read_tail: its last max_bytes bytes, however large.
  std::optional<std::string> read(const std::string& name, std::uint64_t max_bytes) const;
  std::string read_tail(const std::string& name, std::uint64_t max_bytes) const;
  // The names inside (sorted); folders_only: the real folders only (no links).
  std::vector<std::string> names(bool folders_only = false) const;

 private:
  OutFolder(std::filesystem::path path, int fd) : path_(std::move(path)), fd_(fd) {}
  std::optional<std::string> read_file(const std::string& name, std::uint64_t max_bytes, bool tail) const;
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace shadowlab
