// Settings that are never lost: each lab's parameter values, the user's named presets, the window's
// camera (with the name of the scene it looked at: another scene opens framed) and the panel's text
// size, in one JSON file with a version field. What the command line gives the window (--set, --preset,
// --camera) is for one run and not saved for itself (OneOffValues below).
//
//   file      $SHADOWLAB_SETTINGS, else settings.json in the user's config folder: on Linux
//             $XDG_CONFIG_HOME/shadowlab/, else ~/.config/shadowlab/; on macOS
//             ~/Library/Application Support/shadowlab/; on Windows in %APPDATA%\shadowlab
//   writing   under an exclusive lock (settings.json.lock beside it), the file is read again and only
//             what this window changed is merged into it (see save()), so two windows keep each
//             other's labs; then to a temporary file of its own beside it (.settings.json.tmp-<random>,
//             created exclusively, so two windows saving at once never share one), flushed to disk,
//             then renamed over the old file: a reader (or the next run after a crash) sees the old file
//             or the new one, never half of one
//   bad file  one that cannot be used as a whole (not JSON, not an object, no version number, a version
//             this build does not know, "labs" not an object, larger than 4 MiB) is moved aside once to
//             settings.json.bad-YYYYmmdd-HHMMSS, a warning says where, and defaults are used
//   bad entry a lab, its params or presets, or one preset that is not an object, a camera that is not
//             a camera (see camera_problem), a text size that is not a number in 0.5-3, or any value nested
//             deeper than 32 levels, is dropped alone; the warning names each, every other lab's
//             settings are kept, the file as it was is copied aside, and the next save writes the rest
//   unreadable a FIFO, a folder, a file we may not read: defaults, a warning, and nothing is written
//
// CPU only (no GL, no window), so it is tested on its own. Only the window uses it, and only after it
// started; the headless commands never read or write settings, so their runs are reproducible.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/light.h"
#include "core/params.h"

namespace shadowlab {

constexpr int kSettingsVersion = 1;
// The panel's text size, 1 = 100 %: the range its control offers (app/panel_lab.cpp, 50-300 %).
constexpr float kMinTextSize = 0.5f, kMaxTextSize = 3.0f;

// Where settings live (see above); empty when neither SHADOWLAB_SETTINGS nor the variables the
// folder is made from (XDG_CONFIG_HOME, HOME; APPDATA on Windows) are set.
std::filesystem::path default_settings_path();

// Why a stored camera cannot be used (empty when it can): it must be an object with a scene name, a
// target of three finite numbers, a distance, yaw, pitch (within +-90), field of view (1-170 degrees)
// and near and far planes (0 < near < far), as store_camera writes it.
std::string camera_problem(const nlohmann::json& camera);

class Settings {
 public:
  Settings() = default;  // no file: nothing is loaded and save() does nothing

  // Reads `path`. A missing file is not an error (first run). A bad file is moved aside and warning()
  // says so; the settings are then empty, so every lab starts from its defaults. A bad entry is dropped
  // alone (see above). Never throws.
  static Settings load(const std::filesystem::path& path);

  const std::filesystem::path& path() const { return path_; }
  // Empty, or one line for stderr and the panel: what was wrong and where the old file went.
  const std::string& warning() const { return warning_; }

  // Resets `params` to its defaults (the lab's) and applies the values stored for the lab over them.
  // Returns one message per stored value that no longer applies (an unknown key, a value out of range).
  std::vector<std::string> apply_lab(int lab, ParamSet& params) const;
  // Remembers the lab's current values (in memory; save() writes them).
  void store_lab(int lab, const ParamSet& params);

  // Named presets, per lab, kept in the same file. Saving under an existing name replaces it.
  std::vector<std::string> preset_names(int lab) const;
  void save_preset(int lab, const std::string& name, const ParamSet& params);
  // Resets `params` to defaults and applies the preset. Throws std::invalid_argument for an unknown name.
  std::vector<std::string> load_preset(int lab, const std::string& name, ParamSet& params) const;
  void delete_preset(int lab, const std::string& name);

  // The window's camera, kept for the scene it looked at: store_camera remembers it (in memory),
  // camera() gives it back for that scene only (nothing for another scene or none stored).
  void store_camera(const std::string& scene, const OrbitCamera& camera);
  std::optional<OrbitCamera> camera(const std::string& scene) const;

  // The panel's text size (1 = 100 %), one for every lab: nothing when none is stored.
  void store_text_size(float size);
  std::optional<float> text_size() const;

  // Merges this object's changes since it was loaded or last saved (the labs' entries and presets it
  // stored, changed or deleted, the camera) into the file as it is on disk now, under an exclusive lock
  // (settings.json.lock beside it), and writes the result atomically (creating its folder): two windows
  // on one file keep both their labs. Afterwards document() is the merged whole. Throws
  // std::runtime_error with one line naming the file and the reason when it cannot; the previous file
  // is then left as it was. A file found unusable when saving is moved aside first, never written over.
  void save();
  // True when the in-memory settings differ from what was last loaded or saved.
  bool dirty() const { return doc_ != saved_; }

  const nlohmann::json& document() const { return doc_; }

  // For tests: called after the temporary file is written and synced, before the rename.
  std::function<void()> before_rename_for_tests;

 private:
  nlohmann::json& lab_entry(int lab);
  nlohmann::json read_for_merge(const std::filesystem::path& target);
  const nlohmann::json* find_lab_entry(int lab) const;

  std::filesystem::path path_;
  std::string warning_;
  nlohmann::json doc_ = {{"version", kSettingsVersion}, {"labs", nlohmann::json::object()}};
  nlohmann::json saved_ = doc_;  // as last loaded or saved: what save() tells this object's changes from
  // The text of the file load() found bad entries in and copied aside (saving does not copy it again).
  std::string copied_aside_;
  // False when a bad file could not be moved aside: saving would overwrite the only copy of it.
  bool may_write_ = true;
};

// What the command line gives the window for one run (--set, --preset, --camera) is shown but not saved
// for itself: for each such value the settings keep the one it replaced, until the user changes that
// setting in the window; from then on it is the user's own value, saved as any other. (The window
// saves as the user goes, with no Save button, so "changed in the window" is what saving means there.)
// --impl needs nothing here: the implementation shown is never saved. CPU only, tested on its own.
class OneOffValues {
 public:
  // `before`: the lab's values as the settings gave them; `given`: after the command line's.
  void give(int lab, const ParamSet& before, const ParamSet& given);
  void give_camera(const OrbitCamera& camera) { camera_ = camera; }

  // On (re)opening `lab`, whose saved values `params` holds: the given values are set again over them.
  void reapply(int lab, ParamSet& params);
  // What to save for `lab`: `params`, with each given value the user left alone put back to the one it
  // replaced. A value the user changed stops being one-off here.
  ParamSet to_save(int lab, const ParamSet& params);
  // Whether `camera` is still the one given, then not to be kept; once the user moves it, never again.
  bool camera_given(const OrbitCamera& camera);

  bool empty() const { return values_.empty() && !camera_; }

 private:
  struct Value {
    std::string key;
    double saved;  // what the settings held, saved in its place
    double given;  // what the command line set
  };
  int lab_ = -1;
  std::vector<Value> values_;
  std::optional<OrbitCamera> camera_;
};

}  // namespace shadowlab
