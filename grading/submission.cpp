#include "grading/submission.h"

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

std::string error_of(struct archive* a) {
  const char* text = archive_error_string(a);
  return text ? text : "unknown error";
}

// The entry's name (Windows separators made '/'), refused when absolute, when a component is '..', when
// the entry is anything but a file or a folder, when it is sparse, or when its header declares more
// than one file may have.
std::string checked_entry_name(struct archive_entry* entry, const std::string& archive_name, const UnpackLimits& limits) {
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
  if (archive_entry_sparse_count(entry) > 0)
    throw SubmissionError(where + " is a sparse file (holes in place of data); refused");
  if (archive_entry_size_is_set(entry) && archive_entry_size(entry) > static_cast<la_int64_t>(limits.max_file_bytes))
    throw SubmissionError(where + " declares " + std::to_string(archive_entry_size(entry) >> 20) + " MB, more than the " +
                          std::to_string(limits.max_file_bytes >> 20) + " MB a file may have; refused");
  return name;
}

// Copies the data of the entry just read to the writer, counting what is written: a block that does
// not start where the last one ended (a hole) is refused, and so is a file that ends before the size
// its header declares (the writer would extend it with a hole), or one past the limits.
void copy_entry_data(struct archive* reader, struct archive* writer, struct archive_entry* entry,
                     const std::string& archive_name, const std::string& name, const UnpackLimits& limits,
                     std::uint64_t& total) {
  const std::string where = archive_name + ": entry '" + name + "'";
  std::uint64_t file_bytes = 0;
  const void* block = nullptr;
  std::size_t size = 0;
  la_int64_t offset = 0;
  for (;;) {
    const int d = archive_read_data_block(reader, &block, &size, &offset);
    if (d == ARCHIVE_EOF) break;
    if (d != ARCHIVE_OK && d != ARCHIVE_WARN) throw SubmissionError(where + ": " + error_of(reader));
    if (offset < 0 || static_cast<std::uint64_t>(offset) != file_bytes)
      throw SubmissionError(where + " has a hole at byte " + std::to_string(file_bytes) + " (a sparse file); refused");
    file_bytes += size;
    total += size;
    if (file_bytes > limits.max_file_bytes)
      throw SubmissionError(where + " unpacks to more than " + std::to_string(limits.max_file_bytes >> 20) + " MB; refused");
    if (total > limits.max_total_bytes)
      throw SubmissionError(archive_name + ": unpacks to more than " +
                            std::to_string(limits.max_total_bytes >> 20) + " MB; refused");
    if (archive_write_data_block(writer, block, size, offset) != ARCHIVE_OK)
      throw SubmissionError(where + ": " + error_of(writer));
  }
  if (archive_entry_size_is_set(entry) && file_bytes < static_cast<std::uint64_t>(archive_entry_size(entry)))
    throw SubmissionError(where + " holds " + std::to_string(file_bytes) + " bytes, fewer than the " +
                          std::to_string(archive_entry_size(entry)) + " its header declares; refused");
}

void unpack_entries(const fs::path& archive_path, const fs::path& into, const UnpackLimits& limits) {
  const std::string archive_name = archive_path.filename().string();
  ArchivePtr reader(archive_read_new(), archive_read_free);
  archive_read_support_format_zip(reader.get());
  archive_read_support_format_tar(reader.get());
  archive_read_support_format_gnutar(reader.get());
  archive_read_support_filter_all(reader.get());
#if defined(_WIN32)
  const int opened = archive_read_open_filename_w(reader.get(), archive_path.c_str(), 1 << 16);
#else
  const int opened = archive_read_open_filename(reader.get(), archive_path.c_str(), 1 << 16);
#endif
  if (opened != ARCHIVE_OK)
    throw SubmissionError(archive_name + ": cannot open as zip or tar: " + error_of(reader.get()));
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
      throw SubmissionError(archive_name + ": damaged archive: " + error_of(reader.get()));
    if (++entries > limits.max_entries)
      throw SubmissionError(archive_name + ": more than " + std::to_string(limits.max_entries) + " entries; refused");
    const std::string name = checked_entry_name(entry, archive_name, limits);
    const std::string where = archive_name + ": entry '" + name + "'";
    archive_entry_set_pathname(entry, (into / name).string().c_str());
    archive_entry_set_perm(entry, archive_entry_filetype(entry) == AE_IFDIR ? 0755 : 0644);
    if (archive_write_header(writer.get(), entry) != ARCHIVE_OK)
      throw SubmissionError(where + ": " + error_of(writer.get()));
    copy_entry_data(reader.get(), writer.get(), entry, archive_name, name, limits, total);
    if (archive_write_finish_entry(writer.get()) != ARCHIVE_OK)
      throw SubmissionError(where + ": " + error_of(writer.get()));
  }
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
  try {
    unpack_entries(archive_path, into, limits);
  } catch (const SubmissionError& e) {
    // libarchive's own messages name the files where they are on this machine.
    throw SubmissionError(relative_to(relative_to(e.what(), into), archive_path.parent_path()));
  }
}

std::string relative_to(std::string text, const fs::path& folder) {
  std::error_code ec;
  for (const fs::path& f : {fs::absolute(folder, ec), fs::weakly_canonical(folder, ec)}) {
    if (folder.empty() || !f.is_absolute()) continue;
    std::string prefix = f.string();
    while (!prefix.empty() && prefix.back() == '/') prefix.pop_back();
    if (prefix.empty()) continue;
    prefix += '/';
    for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) text.erase(at, prefix.size());
  }
  return text;
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
