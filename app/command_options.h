// What the commands share (render, check, bench, grade and the window): the scene of --scene, the output
// folder of --out, errors as one line for the terminal, and the options --set, --preset, --camera, --size.
#pragma once

#include <string>

#include "core/light.h"
#include "core/params.h"
#include "core/scene.h"

namespace shadowlab {

struct Lab;
struct Preset;

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
// throws std::invalid_argument naming the lab and listing its presets. An empty name does nothing
// (null returned); otherwise the preset, whose view (scene, camera) scene_option and view_camera use.
const Preset* apply_preset_option(ParamSet& params, const Lab& lab, const std::string& name);
// The scene of a run (render, the window): --scene's file (load_scene_or_default), else the preset's
// built-in scene, else the default scene.
Scene scene_option(const std::string& scene_file, const Preset* preset);
// The camera of a run: --camera's, else the preset's camera, else the scene framed (frame_scene_camera).
OrbitCamera view_camera(const std::string& camera_spec, const Preset* preset, const Scene& scene, const ParamSet& params);

// The camera of `--camera "eye=x,y,z target=x,y,z fov=deg"` (render and the window): each part
// optional, what is not given is the framing's (the scene framed from the default angle). A bad spec
// throws std::invalid_argument naming the part.
OrbitCamera camera_option(const std::string& spec, const Bounds& bounds);
// `--size WxH` (the window): throws std::invalid_argument unless both are 16-8192.
void parse_size_option(const std::string& spec, int* width, int* height);

}  // namespace shadowlab
