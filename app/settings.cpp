#include "app/settings.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <stdexcept>

#include "core/platform.h"
#include "core/untrusted.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// A settings file is a few kilobytes; anything this large is not ours and is not read into memory.
constexpr std::uint64_t kMaxSettingsBytes = 4u << 20;
// Settings nest five levels (file, labs, lab, params or presets, preset); a value nested deeper than
// this is dropped while parsing, before anything recursive (copies, comparisons, dumps) can meet it.
constexpr int kMaxSettingsDepth = 32;

std::string lab_key(int lab) { return std::to_string(lab); }

// Why `doc` cannot be used as a whole (it is then moved aside); empty when it can.
std::string file_problem(const nlohmann::json& doc) {
  if (!doc.is_object()) return "is not a JSON object";
  const auto version = doc.find("version");
  // 1.0 is the number 1 (JSON does not tell integers from floats); 1.5 or "1" is no version.
  if (version == doc.end() || !version->is_number() || version->get<double>() != std::trunc(version->get<double>()))
    return "has no version number";
  if (version->get<double>() != kSettingsVersion)
    return "has version " + printable(version->dump(), 40) + "; this build reads version " + std::to_string(kSettingsVersion);
  const auto labs = doc.find("labs");
  if (labs != doc.end() && !labs->is_object()) return "has a \"labs\" entry that is not an object";
  return "";
}

// Drops the entries of `doc` that this build cannot use, one by one, and says which. The rest stays,
// unknown keys and labs included (a newer build may know them).
std::vector<std::string> drop_bad_entries(nlohmann::json& doc) {
  std::vector<std::string> dropped;
  doc["version"] = kSettingsVersion;  // 1.0 written back as 1
  if (!doc.contains("labs")) doc["labs"] = nlohmann::json::object();
  auto& labs = doc["labs"];
  for (auto lab = labs.begin(); lab != labs.end();) {
    const std::string name = "lab " + quote(lab.key(), 40);
    if (!lab->is_object()) {
      dropped.push_back(name + " is not an object");
      lab = labs.erase(lab);
      continue;
    }
    auto& entry = *lab;
    if (entry.contains("params") && !entry["params"].is_object()) {
      dropped.push_back(name + " params are not an object");
      entry.erase("params");
    }
    if (entry.contains("presets")) {
      auto& presets = entry["presets"];
      if (!presets.is_object()) {
        dropped.push_back(name + " presets are not an object");
        entry.erase("presets");
      } else {
        for (auto preset = presets.begin(); preset != presets.end();) {
          if (preset->is_object()) {
            ++preset;
            continue;
          }
          dropped.push_back(name + " preset " + quote(preset.key(), 60) + " is not an object");
          preset = presets.erase(preset);
        }
      }
    }
    ++lab;
  }
  if (doc.contains("camera")) {
    if (std::string problem = camera_problem(doc["camera"]); !problem.empty()) {
      dropped.push_back("the camera " + problem);
      doc.erase("camera");
    }
  }
  if (doc.contains("ui")) {
    auto& ui = doc["ui"];
    if (!ui.is_object()) {
      dropped.push_back("\"ui\" is not an object");
      doc.erase("ui");
    } else if (ui.contains("text_size")) {
      const auto& size = ui["text_size"];
      if (!size.is_number() || !(size.get<double>() >= kMinTextSize && size.get<double>() <= kMaxTextSize)) {
        dropped.push_back("the text size is not a number in 0.5-3");
        ui.erase("text_size");
      }
    }
  }
  return dropped;
}

// Parses with values deeper than kMaxSettingsDepth dropped, each named in `dropped`; a discarded
// document when the text is not JSON. nlohmann's parser keeps its own stack: the deep part is skipped
// as it is read, never built, and then the entry holding it (the value of a lab's parameter, a preset,
// a lab: the first four object keys down from the root) is removed whole.
nlohmann::json parse_bounded(const std::string& text, std::vector<std::string>& dropped) {
  using E = nlohmann::json::parse_event_t;
  std::vector<bool> arrays;       // per open container, from the root: is it an array
  std::vector<std::string> keys;  // per open object: the key being read
  std::vector<std::vector<std::string>> cut;  // the entries that held a dropped value
  const auto callback = [&](int depth, E event, nlohmann::json& parsed) {
    const auto level = static_cast<std::size_t>(depth);
    if (event == E::key) {
      keys.resize(level);
      if (level > 0) keys[level - 1] = parsed.is_string() ? parsed.get<std::string>() : "?";
      return true;
    }
    if (event != E::object_start && event != E::array_start) return true;
    if (depth < kMaxSettingsDepth) {
      arrays.resize(level);
      arrays.push_back(event == E::array_start);
      return true;
    }
    if (depth == kMaxSettingsDepth) {  // the outermost dropped value: find the entry that holds it
      std::vector<std::string> path;
      for (std::size_t i = 0; i < 4 && i < arrays.size() && i < keys.size() && !arrays[i]; ++i) path.push_back(keys[i]);
      std::string shown;
      for (const std::string& k : path) shown += (shown.empty() ? "" : "/") + printable(k, 40);
      dropped.push_back("the value at " + quote(shown, 160) + " nests deeper than " + std::to_string(kMaxSettingsDepth) +
                        " levels");
      cut.push_back(std::move(path));
    }
    return false;
  };
  nlohmann::json doc = nlohmann::json::parse(text, callback, /*allow_exceptions=*/false);
  for (const auto& path : cut) {
    nlohmann::json* at = &doc;
    for (std::size_t i = 0; at && i + 1 < path.size(); ++i)
      at = at->is_object() && at->contains(path[i]) ? &(*at)[path[i]] : nullptr;
    if (at && at->is_object() && !path.empty()) at->erase(path.back());
  }
  return doc;
}

// settings.json.bad-20240131-142501 (with -2, -3... if that name is taken): `path` is moved there, or
// (with `copy`) its `text` is written there, never over an existing file. Returns the new name.
fs::path keep_aside(const fs::path& path, const std::string& text, bool copy) {
  char stamp[32];
  const std::tm local = platform::local_time(std::time(nullptr));
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  fs::path base = path;  // appended to as a path: on Windows it stays UTF-16
  base += std::string(".bad-") + stamp;
  for (int n = 1; n < 1000; ++n) {
    fs::path candidate = base;
    if (n > 1) candidate += "-" + std::to_string(n);
    if (copy ? platform::write_new_file(candidate, text) : platform::rename_no_replace(path, candidate)) return candidate;
  }
  throw platform::FileError(platform::FileProblem::Io, "no free name for a backup beside it");
}

// Copies `text`, the file at `path` as it was read, aside; says where, for a warning.
std::string keep_copy_aside(const fs::path& path, const std::string& text) {
  try {
    return ", the file as it was is kept as " + printable(keep_aside(path, text, /*copy=*/true).string(), 400);
  } catch (const platform::FileError& e) {
    return std::string(" (no copy of the file as it was: ") + e.what() + ")";
  }
}

}  // namespace

std::string camera_problem(const nlohmann::json& camera) {
  if (!camera.is_object()) return "is not an object";
  const auto scene = camera.find("scene");
  if (scene == camera.end() || !scene->is_string()) return "has no scene name";
  const auto target = camera.find("target");
  if (target == camera.end() || !target->is_array() || target->size() != 3) return "has no target x, y, z";
  for (const auto& v : *target)
    if (!v.is_number() || !std::isfinite(v.get<double>())) return "has a target that is not three finite numbers";
  const auto number = [&](const char* key, double* out) {
    const auto it = camera.find(key);
    if (it == camera.end() || !it->is_number() || !std::isfinite(it->get<double>())) return false;
    *out = it->get<double>();
    return true;
  };
  double distance = 0, yaw = 0, pitch = 0, fov = 0, near_plane = 0, far_plane = 0;
  if (!number("distance", &distance) || !number("yaw_deg", &yaw) || !number("pitch_deg", &pitch) ||
      !number("fov_y_deg", &fov) || !number("near_plane", &near_plane) || !number("far_plane", &far_plane))
    return "lacks a finite distance, yaw_deg, pitch_deg, fov_y_deg, near_plane or far_plane";
  if (!(distance > 0.0)) return "has a distance that is not positive";
  if (std::abs(pitch) > 90.0) return "has a pitch beyond +-90 degrees";
  if (fov < 1.0 || fov > 170.0) return "has a field of view outside 1-170 degrees";
  if (!(near_plane > 0.0 && far_plane > near_plane)) return "has planes that are not 0 < near < far";
  return "";
}

fs::path default_settings_path() {
  if (fs::path p = platform::env_path("SHADOWLAB_SETTINGS"); !p.empty()) return p;
  const fs::path folder = platform::user_config_folder();  // per operating system (platform.h)
  return folder.empty() ? fs::path() : folder / "settings.json";
}

namespace {

// What a settings file holds, read as load() reads it.
struct FileContents {
  std::string text;
  nlohmann::json doc;                 // usable as a whole when `problem` is empty
  std::string problem;                // why the file cannot be used as a whole ("is not valid JSON")
  std::vector<std::string> dropped;   // the entries taken out of `doc` (see drop_bad_entries)
};

// Reads and checks `path`. Throws platform::FileError when it cannot be read (missing, a FIFO, a
// folder, not ours to read); a file too large to be ours comes back with its problem instead.
FileContents read_settings(const fs::path& path) {
  FileContents f;
  try {
    f.text = platform::read_regular_file(path, kMaxSettingsBytes);
  } catch (const platform::FileError& e) {
    if (e.problem() != platform::FileProblem::TooLarge) throw;
    f.problem = e.what();
    return f;
  }
  f.doc = parse_bounded(f.text, f.dropped);  // an empty file (what a truncating crash leaves) does not parse
  f.problem = f.doc.is_discarded() ? "is not valid JSON" : file_problem(f.doc);
  if (f.problem.empty())
    for (std::string& d : drop_bad_entries(f.doc)) f.dropped.push_back(std::move(d));
  return f;
}

std::string dropped_list(const std::vector<std::string>& dropped) {
  std::string list;
  for (std::size_t i = 0; i < dropped.size() && i < 8; ++i) list += (i ? "; " : "") + dropped[i];
  if (dropped.size() > 8) list += "; and " + std::to_string(dropped.size() - 8) + " more";
  return list;
}

// Whether save() merges the entries under `key` one by one (the labs, a lab's entry, its presets) at
// this depth, rather than as one value (a lab's params, one preset, the camera).
bool merged_by_entry(int depth, const std::string& key) {
  return (depth == 0 && key == "labs") || depth == 1 || (depth == 2 && key == "presets");
}

// Puts into `disk` what `mine` changed from `base` (what this window last loaded or saved): the entries
// it added or changed, and removes those it removed. Entries this window left alone keep what is on
// disk, which another window may have saved meanwhile.
void merge_changes(nlohmann::json& disk, const nlohmann::json& base, const nlohmann::json& mine, int depth = 0) {
  static const nlohmann::json none = nlohmann::json::object();
  for (const auto& [key, value] : mine.items()) {
    const nlohmann::json& was = base.is_object() && base.contains(key) ? base[key] : none;
    if (base.is_object() && base.contains(key) && was == value) continue;  // unchanged here
    if (merged_by_entry(depth, key) && value.is_object() && disk.contains(key) && disk[key].is_object())
      merge_changes(disk[key], was, value, depth + 1);
    else
      disk[key] = value;
  }
  if (!base.is_object()) return;
  for (const auto& [key, value] : base.items())
    if (!mine.contains(key)) disk.erase(key);
}

}  // namespace

Settings Settings::load(const fs::path& path) {
  Settings s;
  s.path_ = path;
  if (path.empty()) return s;
  const std::string shown = printable(path.string(), 400);
  FileContents f;
  try {
    f = read_settings(path);
  } catch (const platform::FileError& e) {
    if (e.problem() == platform::FileProblem::NotFound) return s;  // first run
    // A FIFO, a folder, a file we may not read: not necessarily bad; never replace what we could not read.
    s.may_write_ = false;
    s.warning_ = shown + ": cannot read: " + e.what() + "; defaults are used and settings will not be saved";
    return s;
  }
  if (f.problem.empty()) {
    s.doc_ = std::move(f.doc);
    s.saved_ = s.doc_;
    if (f.dropped.empty()) return s;
    // Each bad entry is dropped alone; the file as it was is kept beside it, and the next save writes
    // the rest back (dirty() is true until then).
    s.saved_ = nullptr;
    s.warning_ = shown + ": dropped what this build cannot use (" + dropped_list(f.dropped) + "); the other settings are kept" +
                 keep_copy_aside(path, f.text);
    s.copied_aside_ = std::move(f.text);
    return s;
  }
  // Keep the bad file: the user may want what is in it, and a newer build may be able to read it.
  try {
    const fs::path backup = keep_aside(path, f.text, /*copy=*/false);
    s.warning_ = shown + ": " + f.problem + "; kept as " + printable(backup.string(), 400) + ", defaults are used";
  } catch (const platform::FileError& e) {
    s.may_write_ = false;
    s.warning_ = shown + ": " + f.problem + "; it could not be moved aside (" + e.what() +
                 "), so it is left untouched, defaults are used and settings will not be saved";
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

void Settings::store_camera(const std::string& scene, const OrbitCamera& camera) {
  doc_["camera"] = {{"scene", scene},
                    {"target", {camera.target.x, camera.target.y, camera.target.z}},
                    {"distance", camera.distance},
                    {"yaw_deg", camera.yaw_deg},
                    {"pitch_deg", camera.pitch_deg},
                    {"fov_y_deg", camera.fov_y_deg},
                    {"near_plane", camera.near_plane},
                    {"far_plane", camera.far_plane}};
}

std::optional<OrbitCamera> Settings::camera(const std::string& scene) const {
  const auto it = doc_.find("camera");
  if (it == doc_.end() || !camera_problem(*it).empty() || (*it)["scene"].get<std::string>() != scene) return std::nullopt;
  const nlohmann::json& c = *it;
  OrbitCamera camera;
  camera.target = {c["target"][0].get<float>(), c["target"][1].get<float>(), c["target"][2].get<float>()};
  camera.distance = c["distance"].get<float>();
  camera.yaw_deg = c["yaw_deg"].get<float>();
  camera.pitch_deg = c["pitch_deg"].get<float>();
  camera.fov_y_deg = c["fov_y_deg"].get<float>();
  camera.near_plane = c["near_plane"].get<float>();
  camera.far_plane = c["far_plane"].get<float>();
  return camera;
}

void Settings::store_text_size(float size) { doc_["ui"]["text_size"] = std::clamp(size, kMinTextSize, kMaxTextSize); }

std::optional<float> Settings::text_size() const {
  const auto ui = doc_.find("ui");
  if (ui == doc_.end() || !ui->is_object() || !ui->contains("text_size")) return std::nullopt;
  return ui->at("text_size").get<float>();  // checked when loaded (drop_bad_entries)
}

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

// The settings on disk as save() finds them, under its lock: what load() would make of them. A file
// that cannot be used as a whole is moved aside (never written over) and saving starts afresh; one
// with bad entries is copied aside and its good entries kept. One that cannot be read is not replaced.
nlohmann::json Settings::read_for_merge(const fs::path& target) {
  const std::string shown = printable(target.string(), 400);
  FileContents f;
  try {
    f = read_settings(target);
  } catch (const platform::FileError& e) {
    if (e.problem() == platform::FileProblem::NotFound) return {{"version", kSettingsVersion}, {"labs", nlohmann::json::object()}};
    throw std::runtime_error(shown + ": settings not saved: cannot read the file to merge into: " + e.what());
  }
  if (!f.problem.empty()) {
    const fs::path backup = keep_aside(target, f.text, /*copy=*/false);  // throws: then nothing is written
    warning_ = shown + ": " + f.problem + " when saving; kept as " + printable(backup.string(), 400);
    return {{"version", kSettingsVersion}, {"labs", nlohmann::json::object()}};
  }
  if (!f.dropped.empty() && f.text != copied_aside_)  // not the file load() copied aside already
    warning_ = shown + ": dropped what this build cannot use when saving (" + dropped_list(f.dropped) + ")" +
               keep_copy_aside(target, f.text);
  return std::move(f.doc);
}

void Settings::save() {
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
  // Another window may have saved since this one loaded: under the lock, what is on disk now gets this
  // window's changes merged in (its labs' entries, its presets, the camera when it moved it), written to
  // a temporary file of its own, synced, then renamed. The lock file beside it is never renamed.
  fs::path lock_file = target;
  lock_file += ".lock";
  try {
    const platform::FileLock lock(lock_file);
    nlohmann::json merged = read_for_merge(target);
    merge_changes(merged, saved_, doc_);
    // Invalid UTF-8 (a preset name) is replaced rather than thrown on, so one bad name cannot block saving.
    platform::write_file_atomic(target, merged.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n",
                                /*durable=*/true, before_rename_for_tests);
    doc_ = std::move(merged);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(target.string() + ": cannot write settings: " + e.what());
  }
  saved_ = doc_;
}

void OneOffValues::give(int lab, const ParamSet& before, const ParamSet& given) {
  lab_ = lab;
  values_.clear();
  for (const auto& spec : given.specs()) {
    const double was = before.value_or_default(spec), now = given.get(spec.key);
    if (now != was) values_.push_back({spec.key, was, now});
  }
}

void OneOffValues::reapply(int lab, ParamSet& params) {
  if (lab != lab_) return;
  for (Value& v : values_) {
    v.saved = params.get(v.key);  // what the settings hold now is what stays saved
    params.set(v.key, v.given);
  }
}

ParamSet OneOffValues::to_save(int lab, const ParamSet& params) {
  if (lab != lab_ || values_.empty()) return params;
  ParamSet saved = params;
  std::erase_if(values_, [&](const Value& v) {
    if (params.get(v.key) != v.given) return true;  // changed in the window: the user's own value now
    saved.set(v.key, v.saved);
    return false;
  });
  return saved;
}

bool OneOffValues::camera_given(const OrbitCamera& camera) {
  if (!camera_) return false;
  // The planes follow the orbit; where the camera is and looks decides whether the user moved it.
  const OrbitCamera& c = *camera_;
  if (camera.target == c.target && camera.distance == c.distance && camera.yaw_deg == c.yaw_deg &&
      camera.pitch_deg == c.pitch_deg && camera.fov_y_deg == c.fov_y_deg)
    return true;
  camera_.reset();
  return false;
}

}  // namespace shadowlab
