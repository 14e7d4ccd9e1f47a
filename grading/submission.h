// A student's submission as `shadowlab grade` takes it: a folder laid out like the project
// (labs/NN_slug/<exercise files>), or a zip or tar archive of one (unpacked with libarchive).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace shadowlab {

// A submission that cannot be graded as given (a bad archive, no labs/ folder): the student's problem.
class SubmissionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct UnpackLimits {
  std::uint64_t max_total_bytes = 256ull << 20;  // everything unpacked (a zip bomb stops here)
  std::uint64_t max_file_bytes = 16ull << 20;    // one file (an exercise is a few KB)
  std::size_t max_entries = 20000;
};

// True for the names `unpack_archive` takes: .zip, .tar, .tar.gz, .tgz, .tar.xz, .tar.bz2, .tar.zst.
bool is_archive_name(const std::filesystem::path& path);

// The student's name for reports: the folder's name, or the archive's without its extensions, with
// anything but letters, digits and . _ - @ + replaced by _.
std::string submission_name(const std::filesystem::path& path);

// Unpacks `archive` into the empty folder `into`. Refuses (SubmissionError naming the entry, paths
// relative to the submission) absolute paths, entries that leave the folder, links, devices, sparse
// files and files with holes, an entry whose header declares more than the limits allow (before a byte
// of it is written) or more bytes than it holds, and more than the limits allow in all; counts what is
// really written, not what the headers claim.
void unpack_archive(const std::filesystem::path& archive, const std::filesystem::path& into, const UnpackLimits& limits = {});

// `text` with the grading machine's `folder` taken out of the paths in it, so that a student reads
// "labs/02_ortho_fit/exercise.cpp", not where the submission was unpacked: every "<folder>/" (its
// absolute path, and its real path) is removed.
std::string relative_to(std::string text, const std::filesystem::path& folder);

// The folder to grade inside an unpacked or given submission: the one holding labs/, either the
// submission itself or its single top-level folder (archives often wrap everything in one). Throws
// SubmissionError when there is none.
std::filesystem::path find_project_root(const std::filesystem::path& folder);

}  // namespace shadowlab
