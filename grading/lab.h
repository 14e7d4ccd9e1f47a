// A lab: one numbered exercise of the course, and one folder (labs/NN_slug). It declares its
// parameters, switches renderer features on (Features), names the file(s) a student edits (the
// exercise) and their solution, and grades the result headless against the ray-cast oracle (its check).
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.h"
#include "renderer/renderer.h"

namespace shadowlab {

enum class Impl { Exercise, Solution };

// A lab's shader (or C++ exercise) that does not build; what() holds the compiler's messages as
// "file:line:col: error: ...". Whether it is the student's fault is decided by the check runner.
struct BuildError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
const char* impl_name(Impl impl);

// What a preset teaches, declared beside its values: the artifact it provokes with the lab's solution,
// and the preset of the same lab that fixes it. Both empty for a preset that provokes none (a fix, a
// debug view, a setting to compare); fixed_by empty where no preset fixes it (the fix is in the code).
// Artifacts are named in lower case as the course names them: "acne", "peter-panning", "aliasing",
// "perspective aliasing", "light bleeding", ... `shadowlab labs --presets --json` lists them, and a
// test checks that every fixed_by names a preset of its lab.
struct Artifact {
  std::string provokes = {};
  std::string fixed_by = {};
};

// Where a preset looks from, so that its artifact fills the view: a built-in scene (builtin_scene's
// names; empty: the built-in default scene) and a camera as --camera takes it ("eye=x,y,z target=x,y,z
// fov=deg"; empty: the scene framed). `render --preset` and the window use them unless --scene or --camera
// is given; a preset that leaves them empty keeps the view it is applied to.
struct PresetView {
  std::string scene = {};
  std::string camera = {};
};

// The camera of the presets that show a shadow's edge (aliasing, filtering): close over the ground where the
// big box's shadow turns a corner, in the default scene under the default light.
inline constexpr const char* kShadowEdgeCamera = "eye=-4.6,2.2,1.8 target=-3.6,0,-0.4 fov=30";

struct Preset {
  std::string name;         // "acne", "peter-panning", ...
  std::string description;  // what it shows
  std::map<std::string, std::string> values;  // key -> value, as --set takes them
  Artifact artifact = {};   // e.g. {.provokes = "acne", .fixed_by = "tuned"}
  PresetView view = {};     // e.g. {.scene = "stacked", .camera = "eye=0,2,9 target=0,0.5,0"}
};

// What a lab adds to `shadowlab bench`: its solution with these parameters, measured as one technique.
struct BenchTechnique {
  std::string name;    // "hard", "pcf 3", "vsm r4", ...
  std::string family;  // the plot's colour group ("PCF"); the bench adds the lab's number
  std::map<std::string, std::string> sets;  // key -> value, as --set takes them
  bool uses_map = true;  // false: no shadow map (shadow volumes), measured once per scene, map size 0
  bool quick = true;     // also in `bench --quick`
};

struct CheckResult;
class CheckContext;

// The files a run puts in a lab's exercise slots, one per entry of Lab::exercise_files and in that
// order: the student's own, the solution's, a submission's, or a mix (to grade one part at a time).
// Relative paths are under data_dir(); a submission's are absolute.
using SlotFiles = std::vector<std::filesystem::path>;

struct Lab {
  int number = 0;
  std::string slug;   // folder name without the number: "basic_shadow_map"
  std::string title;  // "Basic shadow map"
  std::string summary;  // one line for `shadowlab labs`
  std::vector<ParamSpec> params;  // the lab's own parameters and its changed renderer defaults
  std::vector<Preset> presets;
  // The lab's story: its presets' names in teaching order, stepped through in the window with Page Down /
  // Page Up (demo mode). Empty: the presets in the order they are declared.
  std::vector<std::string> story = {};
  // Files the student edits, relative to the data folder; the solution's files in the same order.
  std::vector<std::string> exercise_files;
  std::vector<std::string> solution_files;
  // GL exercises (C++ with real OpenGL calls: lab 0's gl_shadow_target.cpp) and their solutions, the
  // renderer's own files, in the same order. Not exercise slots: no renderer hook reads them and they are
  // never compiled into the program; the lab's check builds and runs the graded one in a sandbox with its
  // own headless OpenGL context (grading/cpp_exercise.h, `renders`), the file on disk or a submission's.
  std::vector<std::string> gl_exercise_files = {};
  std::vector<std::string> gl_solution_files = {};
  // The C++ exercise files compiled into this program, each with its text as it was built (relative path
  // -> text; labs/CMakeLists.txt embeds them). Check grades the file on disk, never a stale copy: when the
  // file differs from its copy, it is built on its own like a submission's (grading/check.cpp).
  std::map<std::string, std::string_view> compiled_copies;
  // The virtual includes a student's file may use (e.g. "lab/bias.glsl"); any other include in a
  // student's file is refused, so an exercise cannot borrow the solution.
  std::set<std::string> offered_includes;
  // The lab's features with these files in its exercise slots.
  std::function<Features(const SlotFiles&)> make_hooks;
  SlotFiles files(Impl impl) const;
  // make_hooks, with every slot file that is not the solution's confined to offered_includes, and
  // named in messages as the exercise file of its slot (IncludeRules::shown_as).
  Features hooks_for(const SlotFiles& files) const;
  Features hooks(Impl impl) const { return hooks_for(files(impl)); }
  // What the lab adds to `shadowlab bench` (none: the bench does not measure it).
  std::vector<BenchTechnique> bench;
  // Grades the lab headless against the oracle; empty for labs without a check yet.
  std::function<void(CheckContext&, CheckResult&)> check;

  std::string folder() const;  // "labs/00_basic_shadow_map"
  std::filesystem::path text_path() const;  // its README.md: the lab's text
};

// The renderer's parameters with the lab's declared on top (its defaults win).
ParamSet lab_params(const Lab& lab);

// The lab's preset called `name` (as `--preset` takes it); throws std::invalid_argument naming the lab
// and listing its presets when it has none of that name.
const Preset& find_preset(const Lab& lab, const std::string& name);
// The lab's story (Lab::story) as indices into lab.presets; throws std::invalid_argument naming the lab
// when a name is no preset of it or comes twice.
std::vector<std::size_t> story_order(const Lab& lab);
// True when the preset provokes an artifact that only a working exercise draws: the lab has files to
// edit, and the artifact is the one the preset provokes with the lab's solution (Artifact).
bool needs_working_exercise(const Lab& lab, const Preset& preset);
// Sets the preset's values in `params`, over what they hold (as its button in the panel does).
void apply_preset(ParamSet& params, const Preset& preset);
// A preset as the window shows it, so that its picture is the one `render --preset` draws whichever preset
// was shown before: every key some preset of the lab sets goes back to the lab's own value (lab_params),
// then the preset's values are set; the keys no preset sets keep what the student chose.
void show_preset(ParamSet& params, const Lab& lab, const Preset& preset);

// Hooks of a lab whose one slot is the visibility function ("lab/visibility.glsl"), for one light type
// (unset: the light.type parameter decides).
std::function<Features(const SlotFiles&)> visibility_lab_hooks(std::optional<LightType> light = std::nullopt);

}  // namespace shadowlab
