#include "app/panel.h"

#include <imgui.h>

namespace shadowlab {

namespace {

// One widget; returns true when the user changed the value.
bool param_widget(ParamSet& params, const ParamSpec& spec, unsigned& invalidated) {
  double value = params.get(spec.key);
  bool changed = false;
  switch (spec.kind) {
    case ParamKind::Float: {
      auto v = static_cast<float>(value);
      const ImGuiSliderFlags flags = spec.logarithmic ? ImGuiSliderFlags_Logarithmic : ImGuiSliderFlags_None;
      changed = ImGui::SliderFloat(spec.label.c_str(), &v, static_cast<float>(spec.min), static_cast<float>(spec.max),
                                   "%.4g", flags | ImGuiSliderFlags_AlwaysClamp);
      value = v;
      break;
    }
    case ParamKind::Int: {
      int v = static_cast<int>(value);
      changed = ImGui::SliderInt(spec.label.c_str(), &v, static_cast<int>(spec.min), static_cast<int>(spec.max), "%d",
                                 ImGuiSliderFlags_AlwaysClamp);
      value = v;
      break;
    }
    case ParamKind::Bool: {
      bool v = value != 0.0;
      changed = ImGui::Checkbox(spec.label.c_str(), &v);
      value = v ? 1.0 : 0.0;
      break;
    }
    case ParamKind::Choice: {
      int v = static_cast<int>(value);
      if (ImGui::BeginCombo(spec.label.c_str(), spec.choices.at(static_cast<std::size_t>(v)).c_str())) {
        for (std::size_t i = 0; i < spec.choices.size(); ++i) {
          if (ImGui::Selectable(spec.choices[i].c_str(), static_cast<int>(i) == v)) {
            v = static_cast<int>(i);
            changed = true;
          }
        }
        ImGui::EndCombo();
      }
      value = v;
      break;
    }
  }
  if (ImGui::IsItemHovered() && !spec.tooltip.empty()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(spec.tooltip.c_str());
    ImGui::TextDisabled("--set %s=%s", spec.key.c_str(), params.format(spec.key).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  if (changed) invalidated |= params.set(spec.key, value);
  return changed;
}

}  // namespace

unsigned param_widgets(ParamSet& params, const std::function<bool(const ParamSpec&)>& shown) {
  unsigned invalidated = 0;
  for (const auto& spec : params.specs())
    if (shown(spec)) param_widget(params, spec, invalidated);
  return invalidated;
}

}  // namespace shadowlab
