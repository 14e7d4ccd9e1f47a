// Headless commands: render, labs. They share one renderer with the window; only the context differs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/light.h"
#include "core/params.h"
#include "core/scene.h"

namespace shadowlab {

struct Lab;

struct RenderOptions {
  int lab = 0;
  std::string scene_file;  // empty: the built-in default scene
  std::string preset;                    // --preset NAME: one of the lab's presets, under --set
  std::vector<std::string> assignments;  // --set key=value
  std::string camera;  // --camera "eye=x,y,z target=x,y,z fov=deg" (empty: the scene framed)
  int width = 1280;
  int height = 720;
  std::string out_dir;
  bool buffers = false;
  std::string impl = "solution";
  // Draw the window's panel (the same code, ImGui offscreen) over final.png, for reproducible
  // documentation pictures; with panel_check the lab's Check runs first and its result is shown.
  bool panel = false;
  bool panel_check = false;
  std::string bench_file;  // with panel: the Speed against error window on this bench.json
  bool penumbra = false;   // with panel: the Penumbra error window, measured on this frame
  float ui_scale = 1.0f;   // with panel: the text and widget scale (2: as on a 200 % monitor)
};

// Loads --scene or builds the default scene; throws with a message naming the file on failure. What
// the glTF specification says to ignore is ignored with a warning on stderr.
Scene load_scene_or_default(const std::string& path);

// Creates `dir` if missing and proves it writable (a file with a unique name, created exclusively, then
// removed); throws one line naming it.
void prove_writable_folder(const std::string& dir);
// The output folder of a run: prove_writable_folder, then an exclusive lock on it for the rest of the
// process (.shadowlab.lock), so that two runs never mix their outputs in one folder: the second one
// stops at once, saying the folder is in use. Throws one line naming it.
void make_output_dir(const std::string& dir);
// Errors as one line for the terminal: "heading:\ndetail" (e.g. a shader file that cannot be read)
// becomes "heading: detail"; longer messages (compile logs with quoted source) keep their lines.
std::string one_line_error(const std::string& message);

// Applies one `--set key=value` (render and check): a bad one throws std::invalid_argument naming it.
void apply_set_option(ParamSet& params, const std::string& assignment);
// Applies `--preset NAME` (render, check, the window), the lab's preset of that name; an unknown one
// throws std::invalid_argument naming the lab and listing its presets. An empty name does nothing.
void apply_preset_option(ParamSet& params, const Lab& lab, const std::string& name);

// The camera of `--camera "eye=x,y,z target=x,y,z fov=deg"` (render and the window): each part
// optional, what is not given is the framing's (the scene framed from the default angle). A bad spec
// throws std::invalid_argument naming the part.
OrbitCamera camera_option(const std::string& spec, const Bounds& bounds);
// `--size WxH` (the window): throws std::invalid_argument unless both are 16-8192.
void parse_size_option(const std::string& spec, int* width, int* height);
// Exit codes (app/exit_codes.h): 0 written; 2 the command line cannot be used as given; 3 runtime error.
int run_render(const RenderOptions& options);
// `shadowlab labs`: every lab, with --params its parameters, with --presets its presets (the artifact each
// provokes and the preset that fixes it); as JSON with --json.
int run_list_labs(bool show_params, bool json = false, bool show_presets = false);

}  // namespace shadowlab
