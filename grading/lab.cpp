#include "grading/lab.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "renderer/shader.h"

namespace shadowlab {

const char* impl_name(Impl impl) { return impl == Impl::Exercise ? "exercise" : "solution"; }

std::string Lab::folder() const {
  char prefix[8];
  std::snprintf(prefix, sizeof prefix, "%02d_", number);
  return "labs/" + std::string(prefix) + slug;
}

std::filesystem::path Lab::text_path() const { return data_dir() / folder() / "README.md"; }

ParamSet lab_params(const Lab& lab) {
  ParamSet set(renderer_param_specs());
  for (const auto& spec : lab.params) set.declare(spec);
  return set;
}

const Preset& find_preset(const Lab& lab, const std::string& name) {
  std::string names;
  for (const auto& preset : lab.presets) {
    if (preset.name == name) return preset;
    names += (names.empty() ? "'" : ", '") + preset.name + "'";
  }
  const std::string which = "lab " + std::to_string(lab.number) + " (" + lab.title + ")";
  if (names.empty()) throw std::invalid_argument(which + " has no presets");
  throw std::invalid_argument(which + " has no preset '" + name + "'; its presets: " + names);
}

std::vector<std::size_t> story_order(const Lab& lab) {
  std::vector<std::size_t> order;
  if (lab.story.empty()) {
    for (std::size_t i = 0; i < lab.presets.size(); ++i) order.push_back(i);
    return order;
  }
  for (const auto& name : lab.story) {
    const auto i = static_cast<std::size_t>(&find_preset(lab, name) - lab.presets.data());
    if (std::find(order.begin(), order.end(), i) != order.end())
      throw std::invalid_argument("lab " + std::to_string(lab.number) + "'s story names preset '" + name + "' twice");
    order.push_back(i);
  }
  return order;
}

bool needs_working_exercise(const Lab& lab, const Preset& preset) {
  return !lab.exercise_files.empty() && !preset.artifact.provokes.empty();
}

void apply_preset(ParamSet& params, const Preset& preset) {
  for (const auto& [key, value] : preset.values) params.set_from_string(key, value);
}

void show_preset(ParamSet& params, const Lab& lab, const Preset& preset) {
  const ParamSet start = lab_params(lab);
  for (const Preset& other : lab.presets)
    for (const auto& entry : other.values)
      if (params.find(entry.first) && start.find(entry.first)) params.set(entry.first, start.get(entry.first));
  apply_preset(params, preset);
}

SlotFiles Lab::files(Impl impl) const {
  const auto& names = impl == Impl::Exercise ? exercise_files : solution_files;
  return SlotFiles(names.begin(), names.end());
}

Features Lab::hooks_for(const SlotFiles& files) const {
  if (files.size() != exercise_files.size())
    throw std::invalid_argument("lab " + std::to_string(number) + " has " + std::to_string(exercise_files.size()) +
                                " exercise files, not " + std::to_string(files.size()));
  Features hooks = make_hooks(files);
  hooks.include_rules.offered = offered_includes;
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (i >= solution_files.size() || files[i] != std::filesystem::path(solution_files[i]))
      hooks.include_rules.confined.insert(files[i]);
    // Messages name a slot's file as the exercise file the student edits, wherever the graded copy sits.
    if (files[i] != std::filesystem::path(exercise_files[i])) hooks.include_rules.shown_as[files[i]] = exercise_files[i];
  }
  return hooks;
}

std::function<Features(const SlotFiles&)> visibility_lab_hooks(std::optional<LightType> light) {
  return [=](const SlotFiles& files) {
    Features hooks;
    hooks.light = light;
    hooks.includes["lab/visibility.glsl"] = files.at(0).string();
    return hooks;
  };
}

}  // namespace shadowlab
