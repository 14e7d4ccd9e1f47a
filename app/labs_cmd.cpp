#include "app/labs_cmd.h"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "grading/lab.h"
#include "labs/registry.h"

namespace shadowlab {

namespace {

// A lab's presets as `labs --presets --json` lists them: what each sets, the artifact it provokes and the
// preset that fixes it, and its view (the built-in scene and --camera it picks), null where there is none,
// in the lab's order.
nlohmann::json presets_json(const Lab& lab) {
  nlohmann::json presets = nlohmann::json::array();
  const auto or_null = [](const std::string& s) { return s.empty() ? nlohmann::json(nullptr) : nlohmann::json(s); };
  for (const auto& p : lab.presets)
    presets.push_back({{"name", p.name}, {"description", p.description}, {"values", p.values},
                       {"provokes", or_null(p.artifact.provokes)}, {"fixed_by", or_null(p.artifact.fixed_by)},
                       {"scene", or_null(p.view.scene)}, {"camera", or_null(p.view.camera)}});
  return presets;
}

}  // namespace

int run_list_labs(bool show_params, bool json, bool show_presets) {
  if (json) {  // for scripts (graders, the corpus test, lecture pictures): what each lab consists of
    nlohmann::json labs = nlohmann::json::array();
    for (const auto& lab : all_labs()) {
      labs.push_back({{"number", lab.number}, {"slug", lab.slug}, {"folder", lab.folder()}, {"title", lab.title},
                      {"exercise_files", lab.exercise_files}, {"solution_files", lab.solution_files},
                      {"gl_exercise_files", lab.gl_exercise_files}, {"gl_solution_files", lab.gl_solution_files},
                      {"offered_includes", lab.offered_includes}, {"has_check", static_cast<bool>(lab.check)}});
      if (show_presets) {
        labs.back()["presets"] = presets_json(lab);
        nlohmann::json story = nlohmann::json::array();  // the presets in teaching order (the window's Page Down)
        for (const std::size_t i : story_order(lab)) story.push_back(lab.presets[i].name);
        labs.back()["story"] = story;
      }
    }
    std::printf("%s\n", nlohmann::json{{"labs", labs}}.dump(2).c_str());
    return 0;
  }
  for (const auto& lab : all_labs()) {
    std::printf("%2d  %-22s %s\n", lab.number, lab.title.c_str(), lab.summary.c_str());
    if (show_presets) {
      for (const auto& p : lab.presets) {
        std::string artifact;
        if (!p.artifact.provokes.empty()) artifact = "  [" + p.artifact.provokes + "]";
        if (!p.artifact.fixed_by.empty()) artifact += " fixed by '" + p.artifact.fixed_by + "'";
        std::printf("      --preset '%s'%s  %s\n", p.name.c_str(), artifact.c_str(), p.description.c_str());
      }
    }
    if (!show_params) continue;
    const ParamSet params = lab_params(lab);
    for (const auto& s : params.specs()) {
      std::string range;
      if (s.kind == ParamKind::Choice) {
        for (const auto& c : s.choices) range += (range.empty() ? "" : "|") + c;
      } else if (s.kind == ParamKind::Bool) {
        range = "true|false";
      } else {
        range = std::to_string(s.min) + ".." + std::to_string(s.max);
      }
      std::printf("      --set %s=%s  [%s]  %s\n", s.key.c_str(), params.format(s.key).c_str(), range.c_str(), s.label.c_str());
    }
  }
  return 0;
}

}  // namespace shadowlab
