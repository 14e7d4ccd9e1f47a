// What differs between operating systems, in one place: reading files that someone else may control,
// and writing outputs so that nothing planted in a folder can redirect them.
//
// POSIX (Linux, macOS, WSL) uses file descriptors: a model's folder is opened once and every file it
// references is opened relative to that handle, one path component at a time, never following a
// symbolic link blindly (openat with O_NOFOLLOW; a link is read and resolved by hand, and allowed only
// while it stays inside the folder). What was checked is what is read: there is no second lookup by
// path for a swapped link to redirect. Outputs go to a temporary file created exclusively under a
// unique name (O_CREAT|O_EXCL never follows a link) and renamed over the target (a rename replaces a
// planted link, it does not write through it).
//
// Elsewhere (native Windows) a portable fallback with std::filesystem does the same checks by path:
// the same refusals, but a link swapped between check and open is not caught, and output folders are
// not locked. Define SHADOWLAB_PORTABLE_PLATFORM to build the fallback on POSIX (it compiles in CI).
// Paths reach the operating system as std::filesystem paths or, on Windows, as UTF-16 (_wfopen,
// _wgetenv), so a user folder outside the ANSI code page works.
//
// Also here: where per-user settings live, local time, and whether a stream is a terminal.
#pragma once

#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

namespace shadowlab::platform {

enum class FileProblem { NotFound, NotRegular, TooLarge, Outside, Denied, Io };

// A file that cannot be read or written. what() is the reason alone ("is a FIFO, not a regular
// file"), without the file's name: callers name the file the way their message needs.
class FileError : public std::runtime_error {
 public:
  FileError(FileProblem problem, const std::string& why) : std::runtime_error(why), problem_(problem) {}
  FileProblem problem() const { return problem_; }

 private:
  FileProblem problem_;
};

// Reads a whole regular file (a symlink to one is followed: the user named it). FIFOs, devices,
// sockets and folders are refused before any byte is read (and devices before they are opened); so
// is a file larger than max_bytes.
std::string read_regular_file(const std::filesystem::path& path, std::uint64_t max_bytes);

// A folder opened once; files inside it are read relative to that handle.
class Folder {
 public:
  explicit Folder(const std::filesystem::path& dir);  // throws FileError
  ~Folder();
  Folder(Folder&&) noexcept;
  Folder& operator=(Folder&&) = delete;
  Folder(const Folder&) = delete;
  Folder& operator=(const Folder&) = delete;

  // Reads the regular file at `relative` ('/'-separated, already percent-decoded) inside the folder.
  // '.' and '..' and symbolic links are resolved one component at a time on open handles and may not
  // lead out of the folder (FileProblem::Outside), nor may an absolute path or an absolute link. With
  // max_bytes == 0 the file is opened and checked but not read (an empty string is returned).
  std::string read(std::string_view relative, std::uint64_t max_bytes) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Writes `bytes` to `target` atomically: to a new temporary file beside it with a unique name, created
// exclusively (never through a link someone planted), then renamed over the target. A reader sees the
// old file or the new one; two writers never share a temporary file; a failure leaves the old file and
// no temporary one. With `durable` the data and the rename are flushed to disk first (fsync).
// Throws FileError.
// `before_rename` (tests only) runs after the temporary file is written, before the rename.
void write_file_atomic(const std::filesystem::path& target, std::string_view bytes, bool durable = false,
                       const std::function<void()>& before_rename = {});

// Proves `dir` writable by creating a file with a unique name there (exclusively: never through a
// planted link) and removing it. Throws FileError.
void probe_writable(const std::filesystem::path& dir);

// Takes an exclusive lock on `dir` for the rest of this process (a lock file, .shadowlab.lock, holds
// the owner's process id). Returns false, with the other owner's id in `holder` when known, when
// another process holds it; taking it again in the same process succeeds. Throws FileError when the
// lock file cannot be made. The portable fallback does not lock (it returns true).
bool lock_folder(const std::filesystem::path& dir, std::string* holder);

// An exclusive lock on the file `path` (created when missing, empty, never through a link), held from
// construction, which waits for it, to destruction; a process that dies releases it. Two FileLocks on
// one file exclude each other also within one process (flock on its own descriptor; LockFileEx on
// Windows). Lock a file that is never renamed or replaced (not the file the lock guards, when that is
// written by rename). Throws FileError. The portable fallback without Windows does not lock.
class FileLock {
 public:
  explicit FileLock(const std::filesystem::path& path);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  std::intptr_t handle_ = -1;  // a descriptor, or a Windows HANDLE
};

// Renames `from` to `to` unless `to` exists (then returns false and changes nothing). Throws FileError.
bool rename_no_replace(const std::filesystem::path& from, const std::filesystem::path& to);

// Writes `bytes` to a new file `path` that must not exist yet (created exclusively; a link there is not
// followed): returns false, writing nothing, when something already has that name. Throws FileError.
bool write_new_file(const std::filesystem::path& path, std::string_view bytes);

// An environment variable as a path (on Windows read as UTF-16); empty when unset or empty.
std::filesystem::path env_path(const char* name);

// The per-user folder for shadowlab's settings: %APPDATA%\shadowlab on Windows,
// ~/Library/Application Support/shadowlab on macOS, $XDG_CONFIG_HOME/shadowlab or ~/.config/shadowlab
// elsewhere. Empty when the variables it is made from are not set.
std::filesystem::path user_config_folder();

// The user's pictures folder, where the window's screenshots go: %USERPROFILE%\Pictures on Windows,
// ~/Pictures on macOS, elsewhere $XDG_PICTURES_DIR, else the one xdg-user-dirs names in
// $XDG_CONFIG_HOME/user-dirs.dirs (~/.config/user-dirs.dirs; localised names such as ~/Bilder), else
// ~/Pictures. Empty when the variables it is made from are not set. Not created here.
std::filesystem::path user_pictures_folder();

// Local time, thread-safe (localtime_r; localtime_s on Windows).
std::tm local_time(std::time_t t);

// Whether `stream` is a terminal: progress lines use carriage returns only there.
bool is_terminal(std::FILE* stream);

}  // namespace shadowlab::platform
