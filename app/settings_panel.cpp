#include "app/settings_panel.h"

#include <cstdio>

#include <imgui.h>

namespace shadowlab {

namespace {
constexpr auto kAutosaveInterval = std::chrono::seconds(3);
}

void SettingsSession::start() {
  settings_ = Settings::load(default_settings_path());
  started_ = true;
  message_ = settings_.warning();
  if (!message_.empty()) std::fprintf(stderr, "shadowlab: warning: %s\n", message_.c_str());
}

void SettingsSession::open_lab(int lab, ParamSet& params) {
  if (!started_) return;
  for (const auto& problem : settings_.apply_lab(lab, params)) {
    std::fprintf(stderr, "shadowlab: warning: %s\n", problem.c_str());
    message_ = problem;
  }
  one_off_.reapply(lab, params);
}

void SettingsSession::leave_lab(int lab, const ParamSet& params) {
  if (!started_) return;
  settings_.store_lab(lab, one_off_.to_save(lab, params));
  if (settings_.dirty()) save_now();
}

void SettingsSession::autosave(int lab, const ParamSet& params) {
  if (std::chrono::steady_clock::now() - last_save_ < kAutosaveInterval) return;
  leave_lab(lab, params);
  last_save_ = std::chrono::steady_clock::now();
}

std::optional<OrbitCamera> SettingsSession::camera(const std::string& scene) const {
  if (!started_) return std::nullopt;
  return settings_.camera(scene);
}

void SettingsSession::keep_camera(const std::string& scene, const OrbitCamera& camera) {
  if (started_ && !one_off_.camera_given(camera)) settings_.store_camera(scene, camera);
}

std::optional<float> SettingsSession::text_size() const {
  if (!started_) return std::nullopt;
  return settings_.text_size();
}

void SettingsSession::keep_text_size(float size) {
  if (started_) settings_.store_text_size(size);
}

void SettingsSession::save_now() {
  try {
    const std::string before = settings_.warning();
    settings_.save();
    // A file another program broke since the start is moved aside when saving: said like a bad file at start.
    if (settings_.warning() != before) {
      message_ = settings_.warning();
      std::fprintf(stderr, "shadowlab: warning: %s\n", message_.c_str());
    }
  } catch (const std::exception& e) {
    if (message_ != e.what()) std::fprintf(stderr, "shadowlab: %s\n", e.what());
    message_ = e.what();
  }
}

void SettingsSession::draw_presets(int lab, ParamSet& params) {
  if (!started_) return;
  ImGui::PushID("presets");
  ImGui::SetNextItemWidth(140.0f);
  ImGui::InputTextWithHint("##name", "preset name", name_.data(), name_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save")) {
    try {
      settings_.save_preset(lab, name_.data(), params);
      save_now();
    } catch (const std::invalid_argument& e) {
      message_ = e.what();
    }
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140.0f);
  if (ImGui::BeginCombo("Presets", "Load...")) {
    for (const auto& name : settings_.preset_names(lab)) {
      if (ImGui::Selectable(name.c_str())) {
        message_.clear();
        for (const auto& problem : settings_.load_preset(lab, name, params)) message_ = problem;
        std::snprintf(name_.data(), name_.size(), "%s", name.c_str());
      }
    }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) {
    const std::u8string path = settings_.path().u8string();  // ImGui's text is UTF-8; a Windows path is wide
    ImGui::SetTooltip("Saved in %s", reinterpret_cast<const char*>(path.c_str()));
  }
  if (!message_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.7f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", message_.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PopID();
}

}  // namespace shadowlab
