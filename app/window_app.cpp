// What a session in the window does: open a lab, a preset, the lab's story, a dropped scene; the split
// view beside it; the Penumbra error and Speed against error windows' data.
#include "app/window_app.h"

#include <algorithm>
#include <cstdio>

#include "app/command_options.h"
#include "core/gltf_loader.h"
#include "core/untrusted.h"
#include "labs/registry.h"

namespace shadowlab {

void WindowApp::open_lab(const Lab& next, bool wait) {
  if (lab) settings.leave_lab(lab->number, params);
  lab = &next;
  check_result.reset();  // a check still running for the previous lab is dropped when it ends
  params = lab_params(next);
  settings.open_lab(next.number, params);
  lab_text = load_lab_text(next);
  if (compare.with == CompareWith::Preset) compare.preset = 0;
  story_step = -1;
  shown_preset.reset();
  if (compare.with == CompareWith::OtherImpl && next.exercise_files.empty()) compare.with = CompareWith::Defaults;
  apply_hooks(true, wait);
}

// Preset i of the lab (its key, its button, a step of the story), and its caption.
void WindowApp::choose_preset(std::size_t i) {
  const Preset& preset = lab->presets.at(i);
  show_preset(params, *lab, preset);  // the picture render --preset draws, whatever was shown before
  show_preset_view(preset);
  preset_values.clear();
  for (const auto& entry : preset.values) preset_values.emplace_back(entry.first, params.get(entry.first));
  shown_preset = i;
  try {
    const std::vector<std::size_t> order = story_order(*lab);
    const auto at = std::find(order.begin(), order.end(), i);
    if (at != order.end()) story_step = static_cast<int>(at - order.begin());  // the story goes on from here
  } catch (const std::invalid_argument&) {  // said by step_story
  }
}

// One step of the lab's story, forward (+1) or back (-1); it stops at either end.
void WindowApp::step_story(int step) {
  try {
    const std::vector<std::size_t> order = story_order(*lab);
    if (order.empty()) {
      status = "lab " + std::to_string(lab->number) + " has no presets to step through";
      return;
    }
    story_step = std::clamp(story_step + step, 0, static_cast<int>(order.size()) - 1);
    choose_preset(order[static_cast<std::size_t>(story_step)]);
  } catch (const std::invalid_argument& e) {
    status = e.what();
  }
}

// The split view with the solution, same values, on the right (the panel's "Solution beside it").
void WindowApp::show_solution_beside() {
  compare.split = true;
  compare.with = CompareWith::OtherImpl;
  rebuild_split();
}

// The chosen preset, while every value it set still holds.
const Preset* WindowApp::preset_shown() const {
  if (!shown_preset) return nullptr;
  for (const auto& [key, value] : preset_values)
    if (params.get(key) != value) return nullptr;
  return &lab->presets[*shown_preset];
}

void WindowApp::apply_hooks(bool poll_live, bool wait) {
  if (!renderer->set_features(lab->hooks(impl))) status = "shader error: the previous program keeps running";
  live_cpp.reset();  // the renderer runs the compiled copy again: the next poll hands out an edited file's hooks
  // At once, not at the next twice-a-second poll; with `wait` a lab's GL exercise is built before the next
  // frame, so that no frame draws the solution's host code for the student's.
  if (poll_live) {
    live_cpp.poll(*lab, impl, wait);
    if (std::optional<Features> hooks = live_cpp.take_hooks()) use_live_hooks(*hooks);
  }
  rebuild_split();
}

void WindowApp::use_live_hooks(const Features& hooks) {
  if (!renderer->set_features(hooks)) status = "shader error: the previous program keeps running";
}

void WindowApp::rebuild_split() {
  std::string error;
  if (!split.rebuild(*lab, impl, compare, renderer->scene(), &error)) status = "right side: shader error: " + error;
}

// Measures the view against the exact penumbra (at most 640 pixels wide, the window's aspect).
void WindowApp::measure_penumbra(int width, int height) {
  try {
    if (!oracle) oracle = std::make_unique<Oracle>(renderer->scene());
    const int w = std::min(width, 640);
    const int h = std::max(1, height * w / std::max(width, 1));
    penumbra.last = shadowlab::measure_penumbra(*renderer, params, camera, *oracle, w, h);
    penumbra.uploaded = false;
    penumbra.error.clear();
    status = "penumbra measured in " + std::to_string(static_cast<int>(penumbra.last->seconds * 1000.0)) + " ms";
  } catch (const std::exception& e) {
    penumbra.error = shortened(printable(e.what(), kFullErrorBytes), kPanelErrorBytes);
  }
}

// Loads bench.path; a file that cannot be read keeps what was shown and says why.
void WindowApp::load_bench() {
  try {
    bench_plots = load_bench_plots(bench.path);
    bench.error.clear();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", printable(e.what(), kFullErrorBytes).c_str());
    bench.error = shortened(printable(e.what(), kFullErrorBytes), kPanelErrorBytes);
  }
}

void WindowApp::open_scene(const std::string& path) {
  try {
    std::vector<std::string> warnings;  // e.g. an image that cannot be decoded (drawn as a checker)
    const Scene scene = load_gltf(path, {}, &warnings);
    renderer->set_scene(scene);
    scene_from_file = true;
    split.set_scene(scene);
    oracle.reset();
    camera = frame_scene_camera(scene, params);  // the model and its shadow, on the ground it may get
    check_result.reset();
    scene_error.clear();
    status = "opened " + printable(path, 200) + " (" + std::to_string(scene.triangle_count()) + " triangles)";
    for (const std::string& w : warnings) {
      std::fprintf(stderr, "shadowlab: warning: %s: %s\n", printable(path, 400).c_str(), printable(w, 400).c_str());
      status += "; warning: " + shortened(printable(w, 400), kPanelErrorBytes);
    }
  } catch (const std::exception& e) {
    // The whole message on the terminal; the panel shows a bounded part (ImGui's draw lists hold at
    // most 64k vertices: a 60 MB message made it abort). Loader messages are printable already.
    const std::string full = printable(one_line_error(e.what()), kFullErrorBytes);
    std::fprintf(stderr, "shadowlab: cannot open the dropped file: %s\n", full.c_str());
    scene_error = "Cannot open the dropped file: " + shortened(full, kPanelErrorBytes) + " (the current scene stays)";
  }
}

// A preset's button pressed: its built-in scene (when it names one other than the one shown) and its camera.
void WindowApp::show_preset_view(const Preset& preset) {
  if (!preset.view.scene.empty() && preset.view.scene != renderer->scene().name) {
    const Scene scene = builtin_scene(preset.view.scene);  // the names are the lab's own: a test renders each
    renderer->set_scene(scene);
    scene_from_file = false;
    split.set_scene(scene);
    oracle.reset();
    check_result.reset();
    scene_error.clear();
    camera = frame_scene_camera(scene, params);
  }
  if (!preset.view.camera.empty())
    camera = camera_option(preset.view.camera, frame_scene_bounds(renderer->scene(), params));
}

}  // namespace shadowlab
