// A lab: one numbered exercise of the course. It declares its parameters, switches renderer features on
// through LabHooks, names the file(s) a student edits (the exercise) and their solution, and grades the
// result headless against the ray-cast oracle (its check).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

enum class Impl { Exercise, Solution };
const char* impl_name(Impl impl);

struct Preset {
  std::string name;         // "acne", "peter-panning", ...
  std::string description;  // what it shows
  std::map<std::string, std::string> values;  // key -> value, as --set takes them
};

struct CheckResult;
class CheckContext;

struct Lab {
  int number = 0;
  std::string slug;   // folder name without the number: "basic_shadow_map"
  std::string title;  // "Basic shadow map"
  std::string summary;  // one line for `shadowlab labs`
  std::vector<ParamSpec> params;  // the lab's own parameters and its changed renderer defaults
  std::vector<Preset> presets;
  // Files the student edits, relative to the data folder; the solution's files in the same order.
  std::vector<std::string> exercise_files;
  std::vector<std::string> solution_files;
  std::function<LabHooks(Impl)> hooks;
  // Grades the lab headless against the oracle; empty for labs without a check yet.
  std::function<void(CheckContext&, CheckResult&)> check;

  std::string folder() const;  // "labs/00_basic_shadow_map"
  std::filesystem::path text_path() const;  // its README.md: the lab's text
};

const std::vector<Lab>& all_labs();
const Lab* find_lab(int number);

// The renderer's parameters with the lab's declared on top (its defaults win).
ParamSet lab_params(const Lab& lab);

// Hooks of a lab whose exercise is the visibility function for one light type (the spot and point
// light labs): "lab/visibility.glsl" is the exercise or the solution file.
std::function<LabHooks(Impl)> visibility_lab_hooks(LightType light, std::string exercise, std::string solution);

}  // namespace shadowlab
