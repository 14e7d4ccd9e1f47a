// The window's side of the settings file: per-lab values loaded when a lab opens and saved when it is
// left, every few seconds while they change and on exit; the camera and the text size likewise; the
// "Presets" row of the panel. What the command line gave is shown, not saved (OneOffValues). Kept out
// of window.cpp so the window only calls it at those points.
#pragma once

#include <array>
#include <chrono>
#include <optional>
#include <string>

#include "app/settings.h"
#include "core/params.h"

namespace shadowlab {

class SettingsSession {
 public:
  // Loads the settings file (default_settings_path()); a warning goes to stderr and to the panel.
  void start();
  // Applies the lab's stored values over its defaults (`params` holds the lab's parameters), and the
  // command line's one-off values over them when it is the lab they were given for.
  void open_lab(int lab, ParamSet& params);
  // The command line's values for `lab` (`before`: as the settings gave them) and camera: this run's only.
  void give_one_off(int lab, const ParamSet& before, const ParamSet& given) { one_off_.give(lab, before, given); }
  void give_one_off_camera(const OrbitCamera& camera) { one_off_.give_camera(camera); }
  // Stores the lab's values and writes the file if anything changed. A failure is shown, never thrown.
  void leave_lab(int lab, const ParamSet& params);
  // leave_lab, at most every few seconds: a crash loses little, a dragged slider does not hammer the disk.
  void autosave(int lab, const ParamSet& params);
  // The window's camera: the one kept for this scene (none before start(), for another scene, or
  // none kept), and the current one to keep (written with the lab's values, by leave_lab and autosave).
  std::optional<OrbitCamera> camera(const std::string& scene) const;
  void keep_camera(const std::string& scene, const OrbitCamera& camera);
  // The panel's text size: the one kept (none before start() or none kept), and a new one to keep
  // (written with the lab's values).
  std::optional<float> text_size() const;
  void keep_text_size(float size);
  // The "Presets" row: a name field, Save, and a Load list of the lab's saved presets.
  void draw_presets(int lab, ParamSet& params);

 private:
  void save_now();

  Settings settings_;
  OneOffValues one_off_;
  bool started_ = false;  // nothing is written before the window started
  std::string message_;   // the load warning or the last save error, shown in the panel
  std::array<char, 64> name_{};
  std::chrono::steady_clock::time_point last_save_ = std::chrono::steady_clock::now();
};

}  // namespace shadowlab
