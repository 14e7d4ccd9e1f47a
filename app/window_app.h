// The window's state (WindowApp) and the parts of the window built on it: the Check's worker thread
// (app/window_check_worker.cpp), what a session does (app/window_app.cpp: labs, presets, scenes),
// screenshots and the texts over the view (app/window_overlays.cpp). The loop is app/window.cpp.
#pragma once

#include <atomic>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/bench_figures.h"
#include "app/panel_lab.h"
#include "app/settings_panel.h"
#include "app/split_view.h"
#include "grading/check.h"
#include "grading/lab.h"
#include "grading/live_cpp.h"
#include "renderer/renderer.h"

struct GLFWwindow;

namespace shadowlab {

// Error texts: at most this much on the terminal, and this much of it in the panel.
constexpr std::size_t kFullErrorBytes = 4000;
constexpr std::size_t kPanelErrorBytes = 480;

// Creates a window with the highest core profile the driver gives, 4.6 down to 3.3. A hidden one holds
// the context the Check runs in on its worker thread. On failure GLFW's reason is kept (take_glfw_error).
GLFWwindow* create_window(bool visible, int width = 1440, int height = 860);

// The Check in the window: run_lab_check on a worker thread, in the context of a hidden window of its
// own (created, like every window, on the main thread; made current on the worker). It shares no GL
// objects with the view: it builds its own renderer, as `shadowlab check` does, and hands back a
// CheckResult. The view keeps drawing meanwhile; the panel shows the time running and the last run's.
class CheckWorker {
 public:
  CheckWorker() = default;
  CheckWorker(const CheckWorker&) = delete;
  CheckWorker& operator=(const CheckWorker&) = delete;
  ~CheckWorker();  // a check cannot be cancelled; closing waits for it

  bool running() const { return thread_.joinable(); }
  const Lab* lab() const { return lab_; }
  double seconds() const;

  // Starts a check; false (and `error` says why) when no context could be made for it.
  bool start(const Lab& lab, Impl impl, const Scene& scene, bool foreign_scene, std::string* error);
  // The result once the worker has finished (the thread is joined); nothing while it runs.
  std::optional<CheckResult> take_result();

 private:
  GLFWwindow* context_ = nullptr;
  std::thread thread_;
  std::atomic<bool> done_{false};
  const Lab* lab_ = nullptr;
  Impl impl_ = Impl::Exercise;
  double started_ = 0.0;
  std::optional<CheckResult> result_;
};

// The state of one session in the window. Plain members, no statics: the loop (app/window.cpp) owns it.
struct WindowApp {
  GLFWwindow* window = nullptr;
  std::unique_ptr<Renderer> renderer;
  const Lab* lab = nullptr;
  Impl impl = Impl::Exercise;
  ParamSet params;
  OrbitCamera camera;
  LabText lab_text;
  std::string status;       // last screenshot path or error
  // F12's answer, drawn over the view for a few seconds (panel shown or not): where the picture went.
  std::string toast;
  bool toast_error = false;
  double toast_since = -1e9;
  std::string scene_error;  // the last dropped file that could not be opened
  bool scene_from_file = false;  // the scene is a model opened from a file (--scene, dropped): Check grades it as foreign
  bool screenshot_requested = false;
  bool panel_hidden = false;  // H: no ImGui window is built or drawn, nor the pass-time line
  double hidden_since = 0.0;  // when H hid the panel: a hint says how to get it back, for a few seconds
  bool pass_line = true;      // T: the pass-time line (shown while the panel is)
  bool pass_line_shown() const { return pass_line && !panel_hidden; }
  std::string screenshot_path;  // empty: a timestamped name
  bool check_requested = false;
  std::optional<CheckResult> check_result;  // the last Check, for the current lab and implementation
  CheckWorker check_worker;
  LiveCppExercise live_cpp;  // the lab's C++ exercise rebuilt when saved (grading/live_cpp.h)
  std::string live_cpp_said;  // what it said last on the terminal
  std::map<int, double> check_seconds;  // per lab, how long its last check took: the progress bar's estimate
  // Text: fonts rasterised for the monitor's content scale and the user's size (the panel's control).
  UiFonts fonts;
  UiScale ui_scale;
  float text_size = 1.0f;
  float content_scale = 0.0f;  // what the fonts were built for; 0: not yet
  float pixels_per_point = 0.0f;
  bool resize_panel = false;
  std::string gl_summary;
  std::vector<std::string> gl_fallbacks;
  double last_poll = 0.0;
  int last_digit = -1;  // the number key pressed last, and when: a second digit soon after makes lab 10-99
  double last_digit_time = 0.0;
  SettingsSession settings;  // each lab's values and the user's presets, kept in the settings file
  CompareState compare;
  SplitView split;
  Magnifier magnifier;
  int windowed[4] = {0, 0, 1440, 860};  // position and size to return to from fullscreen
  std::vector<std::string> dropped;     // files dropped on the window, opened at the next frame
  BenchPanelState bench;                // the Speed against error window
  std::optional<BenchPlots> bench_plots;
  PenumbraPanelState penumbra;           // the Penumbra error window
  bool penumbra_requested = false;       // its Measure button, done before the next view is drawn
  std::unique_ptr<Oracle> oracle;        // the renderer's scene, for the Penumbra error window; made when first asked
  // Demo mode: the preset last chosen by its key (F1-F10), the story (Page Down / Page Up) or its button
  // in the panel. Its caption stays over the view while the preset's values hold (a moved slider ends it).
  int story_step = -1;                       // position in story_order(*lab); -1: before the first
  std::optional<std::size_t> shown_preset;   // index into lab->presets
  std::vector<std::pair<std::string, double>> preset_values;  // the values it set, as set
  float panel_right = 0.0f;                  // the panel's right edge last frame: the caption centres right of it

  // `wait`: a GL exercise's first build is waited for (at start-up; a lab opened by a key builds in the
  // background: a wait there would split the two digits of a lab's number).
  void open_lab(const Lab& next, bool wait = false);
  // Preset i of the lab (its key, its button, a step of the story), and its caption.
  void choose_preset(std::size_t i);
  // One step of the lab's story, forward (+1) or back (-1); it stops at either end.
  void step_story(int step);
  // The split view with the solution, same values, on the right (the panel's "Solution beside it").
  void show_solution_beside();
  // The chosen preset, while every value it set still holds.
  const Preset* preset_shown() const;
  // The lab's hooks for the implementation shown; with `poll_live`, then at once those of its edited C++
  // or GL exercise file where they are ready (a GL exercise's first build waits for them).
  void apply_hooks(bool poll_live = true, bool wait = false);
  // Hooks a live C++ build made, set on the renderer (the split view's exercise side follows).
  void use_live_hooks(const Features& hooks);
  void rebuild_split();
  // Measures the view against the exact penumbra (at most 640 pixels wide, the window's aspect).
  void measure_penumbra(int width, int height);
  // Loads bench.path; a file that cannot be read keeps what was shown and says why.
  void load_bench();
  void open_scene(const std::string& path);
  // A preset's button pressed: its built-in scene (when it names one other than the one shown) and its camera.
  void show_preset_view(const Preset& preset);
};

// Over the view (app/window_overlays.cpp): the hint after H hid the panel, demo mode's caption, F12's answer.
void draw_hidden_hint(const WindowApp& app);
void draw_caption(const WindowApp& app);
void draw_toast(const WindowApp& app);
// Reads the back buffer and writes it where --screenshot or a script said, else to a new file in the
// screenshot folder (its path shown over the view).
void save_screenshot(WindowApp& app, int width, int height);

}  // namespace shadowlab
