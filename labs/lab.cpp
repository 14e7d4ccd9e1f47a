#include "labs/lab.h"

#include <cstdio>

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

SlotFiles Lab::files(Impl impl) const {
  const auto& names = impl == Impl::Exercise ? exercise_files : solution_files;
  return SlotFiles(names.begin(), names.end());
}

LabHooks Lab::hooks_for(const SlotFiles& files) const {
  if (files.size() != exercise_files.size())
    throw std::invalid_argument("lab " + std::to_string(number) + " has " + std::to_string(exercise_files.size()) +
                                " exercise files, not " + std::to_string(files.size()));
  LabHooks hooks = make_hooks(files);
  hooks.include_rules.offered = offered_includes;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (i >= solution_files.size() || files[i] != std::filesystem::path(solution_files[i]))
      hooks.include_rules.confined.insert(files[i]);
  return hooks;
}

std::function<LabHooks(const SlotFiles&)> visibility_lab_hooks(std::optional<LightType> light) {
  return [=](const SlotFiles& files) {
    LabHooks hooks;
    hooks.light = light;
    hooks.includes["lab/visibility.glsl"] = files.at(0).string();
    return hooks;
  };
}

// Each lab's definition lives in its own folder; this is the list, in the course's order.
Lab make_lab_basic_shadow_map();
Lab make_lab_bias_tuning();
Lab make_lab_ortho_fit();
Lab make_lab_vsm_setup();
Lab make_lab_light_bleeding();
Lab make_lab_moment_blur();
Lab make_lab_pcf();
Lab make_lab_spot_light();
Lab make_lab_point_light();
Lab make_lab_shadow_volumes();

const std::vector<Lab>& all_labs() {
  static const std::vector<Lab> labs = {make_lab_basic_shadow_map(), make_lab_bias_tuning(), make_lab_ortho_fit(),
                                         make_lab_vsm_setup(), make_lab_light_bleeding(), make_lab_moment_blur(),
                                         make_lab_pcf(), make_lab_spot_light(), make_lab_point_light(),
                                         make_lab_shadow_volumes()};
  return labs;
}

const Lab* find_lab(int number) {
  for (const auto& lab : all_labs())
    if (lab.number == number) return &lab;
  return nullptr;
}

}  // namespace shadowlab
