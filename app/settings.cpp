#include "app/settings.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// A settings file is a few kilobytes; anything this large is not ours and is not read into memory.
constexpr std::uintmax_t kMaxSettingsBytes = 16u << 20;

std::string lab_key(int lab) { return std::to_string(lab); }

// Why `doc` is not a settings file this build can use; empty when it is.
std::string structure_problem(const nlohmann::json& doc) {
  if (!doc.is_object()) return "is not a JSON object";
  const auto version = doc.find("version");
  if (version == doc.end() || !version->is_number_integer()) return "has no version number";
  if (version->get<long long>() != kSettingsVersion)
    return "has version " + version->dump() + "; this build reads version " + std::to_string(kSettingsVersion);
  const auto labs = doc.find("labs");
  if (labs == doc.end()) return "";
  if (!labs->is_object()) return "has a \"labs\" entry that is not an object";
  for (const auto& [lab, entry] : labs->items()) {
    if (!entry.is_object()) return "has lab " + lab + " that is not an object";
    if (entry.contains("params") && !entry["params"].is_object()) return "has lab " + lab + " params that are not an object";
    if (entry.contains("presets")) {
      if (!entry["presets"].is_object()) return "has lab " + lab + " presets that are not an object";
      for (const auto& [name, values] : entry["presets"].items())
        if (!values.is_object()) return "has lab " + lab + " preset '" + name + "' that is not an object";
    }
  }
  return "";
}

// settings.json.bad-20240131-142501 (with -2, -3... if that name is taken).
fs::path backup_name(const fs::path& path) {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  const std::string base = path.string() + ".bad-" + stamp;
  fs::path candidate = base;
  std::error_code ec;
  for (int n = 2; fs::exists(candidate, ec); ++n) candidate = base + "-" + std::to_string(n);
  return candidate;
}

std::string errno_text() { return std::strerror(errno); }

// Writes `text` to `tmp` and forces it to disk, so the rename that follows never exposes an empty file
// after a power cut. Throws with a one-line message; removes `tmp` on failure.
void write_synced(const fs::path& target, const fs::path& tmp, const std::string& text) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(target.string() + ": cannot write settings: " + tmp.string() + ": " + errno_text());
  std::size_t done = 0;
  std::string problem;
  while (done < text.size() && problem.empty()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) problem = "write failed: " + errno_text();
    else done += static_cast<std::size_t>(n);
  }
  if (problem.empty() && ::fsync(fd) != 0) problem = "fsync failed: " + errno_text();
  if (::close(fd) != 0 && problem.empty()) problem = "close failed: " + errno_text();
  if (!problem.empty()) {
    ::unlink(tmp.c_str());
    throw std::runtime_error(target.string() + ": cannot write settings: " + problem);
  }
}

}  // namespace

fs::path default_settings_path() {
  if (const char* p = std::getenv("SHADOWLAB_SETTINGS"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return fs::path(x) / "shadowlab" / "settings.json";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".config" / "shadowlab" / "settings.json";
  return {};
}

Settings Settings::load(const fs::path& path) {
  Settings s;
  s.path_ = path;
  if (path.empty()) return s;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return s;  // first run
  if (ec || status.type() != fs::file_type::regular) {
    s.may_write_ = false;
    s.warning_ = path.string() + ": is not a readable file" + (ec ? " (" + ec.message() + ")" : std::string()) +
                 "; defaults are used and settings will not be saved";
    return s;
  }

  std::string problem;
  nlohmann::json doc;
  if (fs::file_size(path, ec) > kMaxSettingsBytes) {
    problem = "is larger than " + std::to_string(kMaxSettingsBytes >> 20) + " MiB";
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in.is_open()) {
      s.may_write_ = false;  // unreadable, not necessarily bad: never replace what we could not read
      s.warning_ = path.string() + ": cannot read: " + errno_text() + "; defaults are used and settings will not be saved";
      return s;
    }
    std::ostringstream text;
    text << in.rdbuf();  // an empty file (what a truncating crash leaves) fails to parse below
    doc = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
    problem = doc.is_discarded() ? "is not valid JSON" : structure_problem(doc);
  }
  if (problem.empty()) {
    s.doc_ = std::move(doc);
    if (!s.doc_.contains("labs")) s.doc_["labs"] = nlohmann::json::object();
    s.saved_ = s.doc_;
    return s;
  }

  // Keep the bad file: the user may want what is in it, and a newer build may be able to read it.
  const fs::path backup = backup_name(path);
  fs::rename(path, backup, ec);
  if (ec) {
    s.may_write_ = false;
    s.warning_ = path.string() + ": " + problem + "; it could not be moved aside (" + ec.message() +
                 "), so it is left untouched, defaults are used and settings will not be saved";
  } else {
    s.warning_ = path.string() + ": " + problem + "; kept as " + backup.string() + ", defaults are used";
  }
  return s;
}

const nlohmann::json* Settings::find_lab_entry(int lab) const {
  const auto labs = doc_.find("labs");
  if (labs == doc_.end()) return nullptr;
  const auto entry = labs->find(lab_key(lab));
  return entry == labs->end() ? nullptr : &*entry;
}

nlohmann::json& Settings::lab_entry(int lab) { return doc_["labs"][lab_key(lab)]; }

std::vector<std::string> Settings::apply_lab(int lab, ParamSet& params) const {
  params.reset_to_defaults();
  const nlohmann::json* entry = find_lab_entry(lab);
  if (!entry || !entry->contains("params")) return {};
  std::vector<std::string> problems = params.apply_json((*entry)["params"]);
  for (auto& p : problems) p = "settings for lab " + lab_key(lab) + ": " + p + " (default used)";
  return problems;
}

void Settings::store_lab(int lab, const ParamSet& params) { lab_entry(lab)["params"] = params.to_json(); }

std::vector<std::string> Settings::preset_names(int lab) const {
  std::vector<std::string> names;
  const nlohmann::json* entry = find_lab_entry(lab);
  if (!entry || !entry->contains("presets")) return names;
  for (const auto& [name, values] : (*entry)["presets"].items()) names.push_back(name);
  return names;  // nlohmann's object keeps keys sorted
}

void Settings::save_preset(int lab, const std::string& name, const ParamSet& params) {
  if (name.empty() || name.find_first_not_of(' ') == std::string::npos)
    throw std::invalid_argument("a preset needs a name");
  lab_entry(lab)["presets"][name] = params.to_json();
}

std::vector<std::string> Settings::load_preset(int lab, const std::string& name, ParamSet& params) const {
  const nlohmann::json* entry = find_lab_entry(lab);
  if (!entry || !entry->contains("presets") || !(*entry)["presets"].contains(name))
    throw std::invalid_argument("lab " + lab_key(lab) + " has no preset '" + name + "'");
  params.reset_to_defaults();
  std::vector<std::string> problems = params.apply_json((*entry)["presets"][name]);
  for (auto& p : problems) p = "preset '" + name + "': " + p + " (default used)";
  return problems;
}

void Settings::delete_preset(int lab, const std::string& name) {
  if (nlohmann::json* labs = doc_.contains("labs") ? &doc_["labs"] : nullptr; labs && labs->contains(lab_key(lab))) {
    nlohmann::json& entry = (*labs)[lab_key(lab)];
    if (entry.contains("presets")) entry["presets"].erase(name);
  }
}

void Settings::save() const {
  if (path_.empty()) return;
  if (!may_write_) throw std::runtime_error(path_.string() + ": settings not saved: the existing file was left untouched (see the warning at start)");
  // A settings file that is a symlink (dotfile managers) stays one: write where it points.
  std::error_code ec;
  const fs::path target = fs::is_symlink(path_, ec) ? fs::weakly_canonical(path_, ec) : path_;
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder))
    throw std::runtime_error(target.string() + ": cannot create the settings folder " + folder.string() +
                             (ec ? ": " + ec.message() : std::string()));
  const fs::path tmp = target.string() + ".tmp";
  // Invalid UTF-8 (a preset name) is replaced rather than thrown on, so one bad name cannot block saving.
  write_synced(target, tmp, doc_.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  if (before_rename_for_tests) before_rename_for_tests();
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    const std::string why = errno_text();
    ::unlink(tmp.c_str());
    throw std::runtime_error(target.string() + ": cannot replace the settings file: " + why);
  }
  // Make the rename itself durable; best effort (some file systems refuse fsync on a folder).
  if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  saved_ = doc_;
}

}  // namespace shadowlab
