#include "app/submission.h"

#include <algorithm>
#include <memory>
#include <vector>

#include <archive.h>
#include <archive_entry.h>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

const char* const kArchiveSuffixes[] = {".tar.gz", ".tar.xz", ".tar.bz2", ".tar.zst", ".tgz", ".tar", ".zip"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::size_t archive_suffix_length(const fs::path& path) {
  const std::string name = lower(path.filename().string());
  for (const char* suffix : kArchiveSuffixes) {
    const std::string s = suffix;
    if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0) return s.size();
  }
  return 0;
}

using ArchivePtr = std::unique_ptr<struct archive, int (*)(struct archive*)>;

// The entry's name (Windows separators made '/'), refused when absolute, when a component is '..', or
// when the entry is anything but a file or a folder.
std::string checked_entry_name(struct archive_entry* entry, const std::string& archive_name) {
  const char* raw = archive_entry_pathname(entry);
  std::string name = raw ? raw : "";
  std::replace(name.begin(), name.end(), '\\', '/');
  const std::string where = archive_name + ": entry '" + name + "'";
  if (name.empty()) throw SubmissionError(archive_name + ": an entry has no name");
  if (name.front() == '/' || (name.size() > 1 && name[1] == ':'))
    throw SubmissionError(where + " has an absolute path; refused");
  for (const auto& part : fs::path(name))
    if (part == "..") throw SubmissionError(where + " leaves the submission's folder ('..'); refused");
  if (archive_entry_hardlink(entry) || archive_entry_symlink(entry))
    throw SubmissionError(where + " is a link; links are refused");
  const auto type = archive_entry_filetype(entry);
  if (type != AE_IFREG && type != AE_IFDIR) throw SubmissionError(where + " is not a file or a folder; refused");
  return name;
}

}  // namespace

bool is_archive_name(const fs::path& path) { return archive_suffix_length(path) > 0; }

std::string submission_name(const fs::path& path) {
  fs::path p = path;
  while (!p.empty() && p.filename().empty()) p = p.parent_path();  // "alice/" -> "alice"
  std::string name = p.filename().string();
  if (const std::size_t n = archive_suffix_length(p); n > 0) name.resize(name.size() - n);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-' && c != '@' && c != '+') c = '_';
  if (name.empty() || name == "." || name == "..") name = "submission";
  return name;
}

void unpack_archive(const fs::path& archive_path, const fs::path& into, const UnpackLimits& limits) {
  const std::string archive_name = archive_path.filename().string();
  ArchivePtr reader(archive_read_new(), archive_read_free);
  archive_read_support_format_zip(reader.get());
  archive_read_support_format_tar(reader.get());
  archive_read_support_format_gnutar(reader.get());
  archive_read_support_filter_all(reader.get());
  if (archive_read_open_filename(reader.get(), archive_path.c_str(), 1 << 16) != ARCHIVE_OK)
    throw SubmissionError(archive_name + ": cannot open as zip or tar: " + archive_error_string(reader.get()));
  // libarchive's own guards as well as ours: no '..', no writing through links, nothing replaced. (Its
  // guard against absolute paths would refuse our own `into` prefix; checked_entry_name refuses those.)
  ArchivePtr writer(archive_write_disk_new(), archive_write_free);
  archive_write_disk_set_options(writer.get(), ARCHIVE_EXTRACT_SECURE_SYMLINKS | ARCHIVE_EXTRACT_SECURE_NODOTDOT |
                                                   ARCHIVE_EXTRACT_NO_OVERWRITE);
  std::uint64_t total = 0;
  std::size_t entries = 0;
  for (;;) {
    struct archive_entry* entry = nullptr;
    const int r = archive_read_next_header(reader.get(), &entry);
    if (r == ARCHIVE_EOF) break;
    if (r != ARCHIVE_OK && r != ARCHIVE_WARN)
      throw SubmissionError(archive_name + ": damaged archive: " + archive_error_string(reader.get()));
    if (++entries > limits.max_entries)
      throw SubmissionError(archive_name + ": more than " + std::to_string(limits.max_entries) + " entries; refused");
    const std::string name = checked_entry_name(entry, archive_name);
    archive_entry_set_pathname(entry, (into / name).c_str());
    archive_entry_set_perm(entry, archive_entry_filetype(entry) == AE_IFDIR ? 0755 : 0644);
    if (archive_write_header(writer.get(), entry) != ARCHIVE_OK)
      throw SubmissionError(archive_name + ": entry '" + name + "': " + archive_error_string(writer.get()));
    std::uint64_t file_bytes = 0;
    const void* block = nullptr;
    std::size_t size = 0;
    la_int64_t offset = 0;
    for (;;) {
      const int d = archive_read_data_block(reader.get(), &block, &size, &offset);
      if (d == ARCHIVE_EOF) break;
      if (d != ARCHIVE_OK && d != ARCHIVE_WARN)
        throw SubmissionError(archive_name + ": entry '" + name + "': " + archive_error_string(reader.get()));
      file_bytes += size;
      total += size;
      if (file_bytes > limits.max_file_bytes)
        throw SubmissionError(archive_name + ": entry '" + name + "' unpacks to more than " +
                              std::to_string(limits.max_file_bytes >> 20) + " MB; refused");
      if (total > limits.max_total_bytes)
        throw SubmissionError(archive_name + ": unpacks to more than " + std::to_string(limits.max_total_bytes >> 20) +
                              " MB; refused");
      if (archive_write_data_block(writer.get(), block, size, offset) != ARCHIVE_OK)
        throw SubmissionError(archive_name + ": entry '" + name + "': " + archive_error_string(writer.get()));
    }
    if (archive_write_finish_entry(writer.get()) != ARCHIVE_OK)
      throw SubmissionError(archive_name + ": entry '" + name + "': " + archive_error_string(writer.get()));
  }
}

fs::path find_project_root(const fs::path& folder) {
  if (fs::is_directory(folder / "labs")) return folder;
  std::vector<fs::path> inner;
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name.front() == '.' || name == "__MACOSX") continue;  // macOS zips add these
    inner.push_back(e.path());
  }
  if (inner.size() == 1 && fs::is_directory(inner[0]) && !fs::is_symlink(inner[0]) && fs::is_directory(inner[0] / "labs"))
    return inner[0];
  throw SubmissionError("no labs/ folder in the submission: lay it out like the project (labs/NN_slug/<your files>)");
}

}  // namespace shadowlab
