// The window: one loop in ImGui's order (poll, new frame, input, panel, render, ImGui, swap). What the
// panel shows is app/panel_lab.cpp, the split view and magnifier app/split_view.cpp, the mouse camera
// app/camera_input.cpp, and scripted input for tests app/input_script.cpp; this file wires them up.
// size: not split yet: issue 37's typed parameter handles and the lecture-hall presets change this file
// (its loop, keys and start) in parallel; after they land, CheckWorker, the screenshots and FrameCost move out.
#include "app/window.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include "renderer/gl.h"  // before GLFW, so GLFW does not include a GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <nlohmann/json.hpp>

#include "app/bench_figures.h"
#include "app/camera_input.h"
#include "app/exit_codes.h"
#include "app/command_options.h"
#include "app/imgui_gl.h"
#include "app/input_script.h"
#include "app/keys.h"
#include "app/panel_lab.h"
#include "app/settings_panel.h"
#include "app/split_view.h"
#include "app/view_annotations.h"
#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/context.h"
#include "core/flashlight.h"
#include "core/gltf_loader.h"
#include "core/image_io.h"
#include "core/platform.h"
#include "renderer/renderer.h"
#include "renderer/shader.h"
#include "core/untrusted.h"

namespace shadowlab {

namespace {

// Error texts: at most this much on the terminal, and this much of it in the panel.
constexpr std::size_t kFullErrorBytes = 4000;
constexpr std::size_t kPanelErrorBytes = 480;

constexpr const char* kHeadlessHint =
    "headless commands work without one: shadowlab render --out DIR, shadowlab labs (see --help)";

// Creates a window with the highest core profile the driver gives, 4.6 down to 3.3. A hidden one holds
// the context the Check runs in on its worker thread. On failure GLFW's reason is kept (take_glfw_error).
GLFWwindow* create_window(bool visible, int width = 1440, int height = 860) {
  const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
  for (const auto& v : versions) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v[0]);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v[1]);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#ifndef NDEBUG
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
    if (GLFWwindow* w = glfwCreateWindow(visible ? width : 1, visible ? height : 1, "shadowlab", nullptr, nullptr)) {
      take_glfw_error();  // the versions refused before this one are not an error
      return w;
    }
  }
  return nullptr;
}

// The Check in the window: run_lab_check on a worker thread, in the context of a hidden window of its
// own (created, like every window, on the main thread; made current on the worker). It shares no GL
// objects with the view: it builds its own renderer, as `shadowlab check` does, and hands back a
// CheckResult. The view keeps drawing meanwhile; the panel shows the time running and the last run's.
class CheckWorker {
 public:
  CheckWorker() = default;
  CheckWorker(const CheckWorker&) = delete;
  CheckWorker& operator=(const CheckWorker&) = delete;
  ~CheckWorker() {
    if (thread_.joinable()) thread_.join();  // a check cannot be cancelled; closing waits for it
    if (context_) glfwDestroyWindow(context_);
  }

  bool running() const { return thread_.joinable(); }
  const Lab* lab() const { return lab_; }
  double seconds() const { return glfwGetTime() - started_; }

  // Starts a check; false (and `error` says why) when no context could be made for it.
  bool start(const Lab& lab, Impl impl, const Scene& scene, std::string* error) {
    if (running()) return false;
    if (!context_) {
      GLFWwindow* current = glfwGetCurrentContext();
      context_ = create_window(false);
      glfwMakeContextCurrent(current);
      if (!context_) {
        *error = "cannot create a context for the Check: " + take_glfw_error();
        return false;
      }
    }
    lab_ = &lab;
    impl_ = impl;
    done_ = false;
    started_ = glfwGetTime();
    thread_ = std::thread([this, scene] {
      glfwMakeContextCurrent(context_);
      try {
        result_ = run_lab_check(*lab_, impl_, scene);
      } catch (const std::exception& e) {
        CheckResult r;
        r.lab = lab_->number;
        r.error = e.what();
        result_ = std::move(r);
      }
      glFinish();
      glfwMakeContextCurrent(nullptr);
      done_ = true;
    });
    return true;
  }

  // The result once the worker has finished (the thread is joined); nothing while it runs.
  std::optional<CheckResult> take_result() {
    if (!running() || !done_) return std::nullopt;
    thread_.join();
    return std::move(result_);
  }

 private:
  GLFWwindow* context_ = nullptr;
  std::thread thread_;
  std::atomic<bool> done_{false};
  const Lab* lab_ = nullptr;
  Impl impl_ = Impl::Exercise;
  double started_ = 0.0;
  std::optional<CheckResult> result_;
};

// The state of one session in the window. Plain members, no statics: the loop below owns it.
struct App {
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
  bool screenshot_requested = false;
  bool panel_hidden = false;  // H: no ImGui window is built or drawn, nor the pass-time line
  double hidden_since = 0.0;  // when H hid the panel: a hint says how to get it back, for a few seconds
  bool pass_line = true;      // T: the pass-time line (shown while the panel is)
  bool pass_line_shown() const { return pass_line && !panel_hidden; }
  std::string screenshot_path;  // empty: a timestamped name
  bool check_requested = false;
  std::optional<CheckResult> check_result;  // the last Check, for the current lab and implementation
  CheckWorker check_worker;
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

  void open_lab(const Lab& next) {
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
    apply_hooks();
  }
  // Preset i of the lab (its key, its button, a step of the story), and its caption.
  void choose_preset(std::size_t i) {
    const Preset& preset = lab->presets.at(i);
    apply_preset(params, preset);
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
  void step_story(int step) {
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
  void show_solution_beside() {
    compare.split = true;
    compare.with = CompareWith::OtherImpl;
    rebuild_split();
  }
  // The chosen preset, while every value it set still holds.
  const Preset* preset_shown() const {
    if (!shown_preset) return nullptr;
    for (const auto& [key, value] : preset_values)
      if (params.get(key) != value) return nullptr;
    return &lab->presets[*shown_preset];
  }
  void apply_hooks() {
    if (!renderer->set_features(lab->hooks(impl))) status = "shader error: the previous program keeps running";
    rebuild_split();
  }
  void rebuild_split() {
    std::string error;
    if (!split.rebuild(*lab, impl, compare, renderer->scene(), &error)) status = "right side: shader error: " + error;
  }
  // Measures the view against the exact penumbra (at most 640 pixels wide, the window's aspect).
  void measure_penumbra(int width, int height) {
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
  void load_bench() {
    try {
      bench_plots = load_bench_plots(bench.path);
      bench.error.clear();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "shadowlab: %s\n", printable(e.what(), kFullErrorBytes).c_str());
      bench.error = shortened(printable(e.what(), kFullErrorBytes), kPanelErrorBytes);
    }
  }
  void open_scene(const std::string& path) {
    try {
      std::vector<std::string> warnings;  // e.g. an image that cannot be decoded (drawn as a checker)
      const Scene scene = load_gltf(path, {}, &warnings);
      renderer->set_scene(scene);
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
  void show_preset_view(const Preset& preset) {
    if (!preset.view.scene.empty() && preset.view.scene != renderer->scene().name) {
      const Scene scene = builtin_scene(preset.view.scene);  // the names are the lab's own: a test renders each
      renderer->set_scene(scene);
      split.set_scene(scene);
      oracle.reset();
      check_result.reset();
      scene_error.clear();
      camera = frame_scene_camera(scene, params);
    }
    if (!preset.view.camera.empty())
      camera = camera_option(preset.view.camera, frame_scene_bounds(renderer->scene(), params));
  }
};

void toggle_fullscreen(App& app) {
  if (glfwGetWindowMonitor(app.window)) {
    glfwSetWindowMonitor(app.window, nullptr, app.windowed[0], app.windowed[1], app.windowed[2], app.windowed[3], 0);
    return;
  }
  GLFWmonitor* monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  if (!mode) {
    app.status = "fullscreen: no monitor found";
    return;
  }
  glfwGetWindowPos(app.window, &app.windowed[0], &app.windowed[1]);
  glfwGetWindowSize(app.window, &app.windowed[2], &app.windowed[3]);
  glfwSetWindowMonitor(app.window, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

// Keys (the list the panel shows is window_keys()), unless ImGui wants the keyboard (typing in a field).
void handle_keys(App& app) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (key_pressed(Key::F12, true)) app.screenshot_requested = true;
  if (key_pressed(Key::F11)) toggle_fullscreen(app);
  // A number key opens that lab; two within kTwoDigitSeconds open lab 10-99 when it exists ("1", "2": 12).
  constexpr double kTwoDigitSeconds = 0.8;
  for (int n = 0; n <= 9; ++n) {
    if (!digit_pressed(n)) continue;
    const double now = glfwGetTime();
    const Lab* two = app.last_digit > 0 && now - app.last_digit_time < kTwoDigitSeconds ? find_lab(app.last_digit * 10 + n) : nullptr;
    const Lab* lab = two ? two : find_lab(n);
    app.last_digit = two ? -1 : n;
    app.last_digit_time = now;
    if (lab && lab != app.lab) app.open_lab(*lab);
  }
  // F1-F10: the lab's presets in their declared order; Page Down / Page Up (a presenter's remote) its story.
  for (int n = 1; n <= 10; ++n)
    if (function_key_pressed(n) && static_cast<std::size_t>(n) <= app.lab->presets.size()) app.choose_preset(static_cast<std::size_t>(n - 1));
  if (key_pressed(Key::PageDown)) app.step_story(+1);
  if (key_pressed(Key::PageUp)) app.step_story(-1);
  if (key_pressed(Key::N)) app.open_lab(*neighbour_lab(*app.lab, +1));
  if (key_pressed(Key::P)) app.open_lab(*neighbour_lab(*app.lab, -1));
  if (key_pressed(Key::S)) {
    app.compare.split = !app.compare.split;
    app.rebuild_split();
  }
  if (key_pressed(Key::M)) app.compare.magnifier = !app.compare.magnifier;
  if (key_pressed(Key::H)) {
    app.panel_hidden = !app.panel_hidden;
    app.hidden_since = glfwGetTime();
  }
  if (key_pressed(Key::T)) app.pass_line = !app.pass_line;
  // R: the camera a first start gives, the scene framed (lost in an orbit, or after --camera).
  if (key_pressed(Key::R)) app.camera = frame_scene_camera(app.renderer->scene(), app.params);
}

// For a few seconds after the panel is hidden, one line in the corner says how to get it back; then
// nothing is drawn over the view.
void draw_hidden_hint(const App& app) {
  constexpr double kHintSeconds = 3.0;
  if (glfwGetTime() - app.hidden_since > kHintSeconds) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(10.0f, display.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##panel hidden", nullptr, flags)) ImGui::TextUnformatted("Panel hidden: press H to show it");
  ImGui::End();
}

// Fonts and style for the window's monitor and the user's text size; rebuilt (between frames) when
// either changes, e.g. when the window moves to a monitor with another scale.
void update_ui_scale(App& app) {
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(app.window, &sx, &sy);
  int ww = 0, wh = 0, fw = 0, fh = 0;
  glfwGetWindowSize(app.window, &ww, &wh);
  glfwGetFramebufferSize(app.window, &fw, &fh);
  const float ppp = ww > 0 && fw > 0 ? static_cast<float>(fw) / static_cast<float>(ww) : 1.0f;
  const UiScale next = plan_ui_scale(sx, ppp, app.text_size);
  if (app.content_scale == sx && app.pixels_per_point == ppp && next.raster == app.ui_scale.raster && app.fonts.body) return;
  app.content_scale = sx;
  app.pixels_per_point = ppp;
  app.ui_scale = next;
  std::string warning;
  app.fonts = build_ui_fonts(*ImGui::GetIO().Fonts, data_dir() / "assets" / "fonts", next.raster, &warning);
  if (!warning.empty()) std::fprintf(stderr, "shadowlab: warning: %s\n", warning.c_str());
  remake_font_texture();
  apply_ui_style(next);
  app.resize_panel = true;
}

void draw_panel(App& app) {
  PanelModel model;
  model.lab = app.lab;
  model.impl = app.impl;
  model.params = &app.params;
  model.stats = &app.renderer->stats();
  model.triangles = app.renderer->scene().triangle_count();
  model.scene_name = app.renderer->scene().name;
  model.scene_error = app.scene_error;
  model.lab_text = &app.lab_text;
  model.fonts = &app.fonts;
  model.ui_scale = app.ui_scale.style;
  model.resize = app.resize_panel;
  model.text_size = app.text_size;
  model.gl_summary = app.gl_summary;
  model.gl_fallbacks = app.gl_fallbacks;
  if (app.check_worker.running() && app.check_worker.lab() == app.lab) {
    model.check_progress.running = true;
    model.check_progress.seconds = app.check_worker.seconds();
    const auto last = app.check_seconds.find(app.lab->number);
    model.check_progress.expected = last == app.check_seconds.end() ? 0.0 : last->second;
  }
  model.check = app.check_result ? &*app.check_result : nullptr;
  model.shader_error = app.renderer->shader_error();
  model.status = app.status;
  model.compare = &app.compare;
  model.settings = &app.settings;
  model.bench = &app.bench;
  model.bench_plots = app.bench_plots ? &*app.bench_plots : nullptr;
  model.penumbra = &app.penumbra;
  model.penumbra_key = app.penumbra.open ? penumbra_view_key(app.params, app.camera) : std::string();
  const bool bench_was_open = app.bench.open;
  const PanelActions actions = draw_lab_panel(model);
  app.resize_panel = false;
  app.panel_right = actions.panel_right;
  if (actions.preset) app.choose_preset(*actions.preset);
  if (actions.solution_beside) app.show_solution_beside();
  if (actions.text_size) {
    app.text_size = *actions.text_size;  // fonts rebuilt before the next frame
    app.settings.keep_text_size(app.text_size);
  }
  if (!actions.copied_link.empty()) app.status = "copied to the clipboard: " + actions.copied_link;
  if (actions.load_bench || (app.bench.open && !bench_was_open && !app.bench_plots && app.bench.error.empty()))
    app.load_bench();
  if (actions.open_lab && actions.open_lab != app.lab) app.open_lab(*actions.open_lab);
  if (actions.impl && *actions.impl != app.impl) {
    app.impl = *actions.impl;
    app.check_result.reset();
    app.apply_hooks();
  }
  if (actions.compare_changed) app.rebuild_split();
  if (actions.check) app.check_requested = true;
  if (actions.measure_penumbra) app.penumbra_requested = true;
  if (actions.screenshot) app.screenshot_requested = true;
  if (actions.fullscreen) toggle_fullscreen(app);
}

// Where F12 saves: $SHADOWLAB_SCREENSHOTS, else a shadowlab folder in the user's pictures folder (see
// platform::user_pictures_folder), else (no home folder) the working folder. Not the working folder
// first: a window started from a launcher or an IDE has one the user never sees (the build folder, /).
std::filesystem::path screenshot_folder() {
  if (std::filesystem::path p = platform::env_path("SHADOWLAB_SCREENSHOTS"); !p.empty()) return p;
  const std::filesystem::path pictures = platform::user_pictures_folder();
  return pictures.empty() ? std::filesystem::current_path() : pictures / "shadowlab";
}

// A new file there, made with its folder: shadowlab-lab01-20261127-201501.png (-2, -3... within a second).
std::filesystem::path new_screenshot_file(int lab) {
  const std::filesystem::path folder = std::filesystem::absolute(screenshot_folder());
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder))
    throw std::runtime_error(folder.string() + ": cannot create the screenshot folder" + (ec ? ": " + ec.message() : std::string()));
  char stem[64];
  const std::tm now = platform::local_time(std::time(nullptr));
  const int used = std::snprintf(stem, sizeof stem, "shadowlab-lab%02d-", lab);
  std::strftime(stem + used, sizeof stem - static_cast<std::size_t>(used), "%Y%m%d-%H%M%S", &now);
  for (int n = 1; n < 1000; ++n) {
    const std::filesystem::path path = folder / (std::string(stem) + (n > 1 ? "-" + std::to_string(n) : "") + ".png");
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return path;
  }
  throw std::runtime_error(folder.string() + ": no free name for a screenshot");
}

void save_screenshot(App& app, int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  flip_rows(rgba, width, height, 4);
  // A path given by --screenshot or a script is the caller's: written there, nothing shown over the view.
  if (!app.screenshot_path.empty()) {
    try {
      write_png(app.screenshot_path, width, height, rgba);
      app.status = "saved " + std::filesystem::absolute(app.screenshot_path).string();
    } catch (const std::exception& e) {
      app.status = e.what();
    }
    return;
  }
  // F12 or the panel's button: a new file in the screenshot folder, and its full path over the view.
  app.toast_since = glfwGetTime();
  try {
    const std::filesystem::path path = new_screenshot_file(app.lab->number);
    write_png(path, width, height, rgba);
    const std::u8string utf8 = path.u8string();  // ImGui's text is UTF-8; a Windows path is wide
    const std::string shown(reinterpret_cast<const char*>(utf8.c_str()));
    app.status = "saved " + shown;
    app.toast = "Screenshot saved to " + shown;
    app.toast_error = false;
    std::printf("shadowlab: screenshot saved to %s\n", shown.c_str());
    std::fflush(stdout);
  } catch (const std::exception& e) {
    app.status = e.what();
    app.toast = "Screenshot not saved: " + shortened(printable(e.what(), kFullErrorBytes), kPanelErrorBytes);
    app.toast_error = true;
    std::fprintf(stderr, "shadowlab: screenshot not saved: %s\n", e.what());
  }
}

// Demo mode's caption: the chosen preset's name and what it shows, large enough to read from the back of a
// lecture hall, centred at the top of the view right of the panel, while its values hold.
void draw_caption(const App& app) {
  const Preset* preset = app.preset_shown();
  if (!preset) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float left = app.panel_hidden ? 0.0f : std::min(app.panel_right, display.x * 0.5f);
  const float width = display.x - left;
  const float top = app.pass_line_shown() ? ImGui::GetFrameHeight() + 16.0f : 10.0f;  // under the pass-time line
  ImGui::SetNextWindowPos(ImVec2(left + width * 0.5f, top), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(width - 20.0f, display.y * 0.5f));
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin("##caption", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::PushTextWrapPos(width - 40.0f);
  std::string place;
  try {
    const auto order = story_order(*app.lab);
    const auto at = std::find(order.begin(), order.end(), *app.shown_preset);
    if (at != order.end()) place = "  " + std::to_string(at - order.begin() + 1) + "/" + std::to_string(order.size());
  } catch (const std::invalid_argument&) {
  }
  if (app.fonts.caption) ImGui::PushFont(app.fonts.caption);
  ImGui::TextUnformatted(preset->name.c_str());
  if (app.fonts.caption) ImGui::PopFont();
  if (app.fonts.caption_text) ImGui::PushFont(app.fonts.caption_text);
  if (!place.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("Lab %d%s", app.lab->number, place.c_str());
  }
  ImGui::TextUnformatted(preset->description.c_str());
  if (app.impl == Impl::Exercise && needs_working_exercise(*app.lab, *preset))
    ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.45f, 1.0f), "Your exercise shows %s once it works; the solution's picture: \"Solution beside it\" in the panel",
                       preset->artifact.provokes.c_str());
  if (app.fonts.caption_text) ImGui::PopFont();
  ImGui::PopTextWrapPos();
  ImGui::End();
}

// F12's answer over the view for a few seconds, at the bottom centre (over the view, in front of the panel).
void draw_toast(const App& app) {
  constexpr double kToastSeconds = 5.0;
  if (app.toast.empty() || glfwGetTime() - app.toast_since > kToastSeconds) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y - 10.0f), ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::PushTextWrapPos(display.x * 0.8f);  // a long path wraps rather than leaving the window
  ImGui::Begin("##screenshot", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  if (app.toast_error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.45f, 1.0f));
  ImGui::TextUnformatted(app.toast.c_str());
  if (app.toast_error) ImGui::PopStyleColor();
  ImGui::End();
  ImGui::PopTextWrapPos();
}

// One frame of the 3D view: the left (or only) side, the right side of a split, the magnifier's crop,
// and the GPU-time line. ImGui's draw data is rendered after this.
void render_view(App& app, int width, int height) {
  FrameRequest request;
  request.camera = app.camera;
  request.width = width;
  request.height = height;
  request.to_window = true;  // drawn where it is seen: the split view and the magnifier read it there too
  app.renderer->render(app.params, request);
  if (app.compare.split)
    app.split.compose(app.split.right_params(*app.lab, app.params, app.compare), request, app.compare, *app.lab, app.impl);
  if (app.compare.magnifier) {
    app.magnifier.capture(width, height);
    app.magnifier.draw();
  }
  // The debug quads' labels and the false-colour legends, each side's over its own part of the view.
  const float display_width = ImGui::GetIO().DisplaySize.x;
  const DebugAnnotations* right = app.compare.split ? app.split.annotations() : nullptr;
  const float divider = right ? app.compare.divider * display_width : display_width;
  draw_view_annotations(app.renderer->annotations(), width, height, 0.0f, divider);
  if (right) draw_view_annotations(*right, width, height, divider, display_width);
  if (app.pass_line_shown()) draw_pass_overlay(app.renderer->stats(), app.compare.split ? app.split.stats() : nullptr);
}

// What the interactive frames cost, for --frame-report: frame times, and the glFinish calls and
// blocking query reads (the window's renderers) with the pass-time line shown and hidden.
struct FrameCost {
  struct Side {
    long frames = 0, gl_finishes = 0, blocking_reads = 0;
  };
  Side shown, hidden;
  std::vector<double> frame_ms;  // from the start of one frame to the next, after the first few

  static long finishes(const App& app) {
    const FrameStats* right = app.split.stats();
    return app.renderer->stats().gl_finishes + (right ? right->gl_finishes : 0);
  }
  static long blocking(const App& app) {
    const FrameStats* right = app.split.stats();
    return app.renderer->stats().blocking_query_reads + (right ? right->blocking_query_reads : 0);
  }
  void write(const std::string& path, const App& app) const {
    auto side = [](const Side& s) {
      return nlohmann::json{{"frames", s.frames}, {"gl_finishes", s.gl_finishes}, {"blocking_query_reads", s.blocking_reads}};
    };
    nlohmann::json j = {{"timers_work", app.renderer->timers_work()},
                        {"frames_timed", frame_ms.size()},
                        {"median_frame_ms", median(frame_ms)},
                        {"pass_line_shown", side(shown)},
                        {"pass_line_hidden", side(hidden)}};
    write_text_atomic(path, j.dump(2) + "\n");
  }
};

void drop_callback(GLFWwindow* window, int count, const char** paths) {
  auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
  for (int i = 0; app && i < count; ++i) app->dropped.emplace_back(paths[i]);
}

// size: 92 lines, not split yet for the same reason as the file (see its head).
void run_loop(App& app, const WindowOptions& options, InputScript& script) {
  int frame = 0;
  FrameCost cost;
  if (!options.frame_report.empty()) cost.frame_ms.reserve(options.frames > 0 ? static_cast<std::size_t>(options.frames) : 1024);
  double frame_start = glfwGetTime();
  constexpr int kWarmUpFrames = 5;  // shaders compile, targets are made
  while (!glfwWindowShouldClose(app.window)) {
    const std::string scripted_shot = script.advance(app.window, glfwGetTime());
    if (!scripted_shot.empty()) {
      app.screenshot_requested = true;
      app.screenshot_path = scripted_shot;
    }
    glfwPollEvents();
    for (const auto& path : app.dropped) app.open_scene(path);
    app.dropped.clear();
    int width = 0, height = 0;
    glfwGetFramebufferSize(app.window, &width, &height);
    if (width == 0 || height == 0) {  // minimised: nothing to draw
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    update_ui_scale(app);
    if (auto result = app.check_worker.take_result()) {
      const Lab* checked = app.check_worker.lab();
      app.check_seconds[result->lab] = result->seconds;
      if (checked == app.lab && result->impl == app.impl) app.check_result = std::move(result);
    }
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (!app.split.handle_divider(app.compare)) orbit_pan_zoom(app.camera, app.renderer->scene().bounds());
    handle_keys(app);
    // Students' edits to shader files reload live; checking twice a second is plenty.
    if (glfwGetTime() - app.last_poll > 0.5) {
      app.renderer->poll_shader_files();
      app.split.poll_shader_files();
      app.last_poll = glfwGetTime();
      app.settings.keep_camera(app.renderer->scene().name, app.camera);
      app.settings.autosave(app.lab->number, app.params);
    }
    if (!app.panel_hidden) draw_panel(app);
    else draw_hidden_hint(app);
    draw_caption(app);
    draw_toast(app);
    if (script.take_check_request()) app.check_requested = true;
    if (script.take_solution_beside_request()) app.show_solution_beside();
    if (app.penumbra_requested) {
      app.measure_penumbra(width, height);
      app.penumbra_requested = false;
    }
    if (app.check_requested) {
      std::string error;
      if (!app.check_worker.start(*app.lab, app.impl, app.renderer->scene(), &error)) app.status = error;
      app.check_requested = false;
    }
    // The pass-time line decides how passes are timed: for nothing, where it is not shown and the
    // driver's timer queries are useless; never by waiting for the GPU where they work.
    const TimingMode timing = interactive_timing(app.renderer->timers_work(), app.pass_line_shown());
    app.renderer->set_timing(timing);
    app.split.set_timing(timing);
    // The flashlight's node circles the scene while flashlight.animate is on (only its map is redrawn).
    if (app.params.get(param::flashlight_animate))
      app.params.set("flashlight.phase", advance_flashlight_phase(app.params, glfwGetTime() - frame_start));
    const long finishes_before = FrameCost::finishes(app), blocking_before = FrameCost::blocking(app);
    render_view(app, width, height);
    FrameCost::Side& side = app.pass_line_shown() ? cost.shown : cost.hidden;
    ++side.frames;
    side.gl_finishes += FrameCost::finishes(app) - finishes_before;
    side.blocking_reads += FrameCost::blocking(app) - blocking_before;
    ImGui::Render();
    // With the panel hidden and no line, hint, label or legend shown there is nothing over the view to draw.
    if (ImGui::GetDrawData()->TotalVtxCount > 0) ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    ++frame;
    script.frame_drawn();
    const bool last_frame = (options.frames > 0 && frame >= options.frames) || (!script.empty() && script.finished());
    if (last_frame && !options.screenshot.empty()) {
      app.screenshot_requested = true;
      app.screenshot_path = options.screenshot;
    }
    if (app.screenshot_requested) {
      save_screenshot(app, width, height);
      app.screenshot_requested = false;
      app.screenshot_path.clear();
    }
    glfwSwapBuffers(app.window);
    const double now = glfwGetTime();
    if (frame > kWarmUpFrames && !options.frame_report.empty()) cost.frame_ms.push_back(1000.0 * (now - frame_start));
    frame_start = now;
    if (last_frame) glfwSetWindowShouldClose(app.window, GLFW_TRUE);
  }
  if (!options.frame_report.empty()) cost.write(options.frame_report, app);
}

}  // namespace

// size: 126 lines, not split yet for the same reason as the file (see its head).
int run_window(const WindowOptions& options) {
  const Lab* lab = find_lab(options.lab);
  if (!lab) {
    std::fprintf(stderr, "shadowlab: no lab %d (see `shadowlab labs`)\n", options.lab);
    return kExitUsage;
  }
  std::optional<InputScript> script;
  try {
    script.emplace(options.script);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return kExitUsage;
  }
  Scene scene;
  const Preset* preset = nullptr;
  ParamSet check = lab_params(*lab);
  try {
    preset = apply_preset_option(check, *lab, options.preset);
    scene = scene_option(options.scene_file, preset);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", one_line_error(e.what()).c_str());
    return kExitUsage;
  }
  int width = 1440, height = 860;
  OrbitCamera camera;
  try {
    if (!options.size.empty()) parse_size_option(options.size, &width, &height);
    for (const auto& a : options.assignments) apply_set_option(check, a);
    camera = view_camera(options.camera, preset, scene, check);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return kExitUsage;
  }
  std::optional<BenchPlots> bench;  // asked for on the command line: read it now, or say why not
  try {
    if (!options.bench_file.empty()) bench = load_bench_plots(options.bench_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return kExitUsage;
  }
  capture_glfw_errors();
  if (!glfwInit()) {
    std::fprintf(stderr, "shadowlab: cannot open a window: %s; %s\n", take_glfw_error().c_str(), kHeadlessHint);
    return kExitRuntime;
  }
  GLFWwindow* window = create_window(true, width, height);
  if (!window) {
    std::fprintf(stderr, "shadowlab: cannot create an OpenGL 3.3 core window: %s; %s\n", take_glfw_error().c_str(),
                 kHeadlessHint);
    glfwTerminate();
    return kExitRuntime;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
#ifndef NDEBUG
  enable_gl_debug_output();
#endif

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // window layout is not worth a file in the user's folder
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  try {
    App app;
    app.window = window;
    app.gl_summary = gl_summary();
    app.gl_fallbacks = gl_fallbacks();
    app.renderer = std::make_unique<Renderer>();
    app.renderer->set_scene(scene);
    app.camera = camera;
    app.windowed[2] = width;
    app.windowed[3] = height;
    app.bench.path = options.bench_file.empty() ? (data_dir() / "docs" / "bench.json").string() : options.bench_file;
    app.bench_plots = std::move(bench);
    app.bench.open = app.bench_plots.has_value();
    app.impl = options.impl == "solution" ? Impl::Solution : Impl::Exercise;  // never saved: one-off as it is
    app.settings.start();  // only now: a run that failed to start never touches the settings file
    if (const auto size = app.settings.text_size()) app.text_size = *size;
    // The camera kept for this scene, unless --camera or the preset's view chose one (for this run: kept once
    // the user moves it).
    if (options.camera.empty() && (!preset || preset->view.camera.empty())) {
      if (const auto kept = app.settings.camera(scene.name)) app.camera = *kept;
    } else {
      app.settings.give_one_off_camera(camera);
    }
    app.open_lab(*lab);
    // --preset, then --set, over the saved values: shown in this run, saved only if changed in the window.
    const ParamSet saved = app.params;
    apply_preset_option(app.params, *lab, options.preset);
    for (const auto& a : options.assignments) apply_set_option(app.params, a);
    app.settings.give_one_off(lab->number, saved, app.params);
    // Said in the panel, so that a value missing at the next start is no surprise.
    std::string one_off;
    if (!options.preset.empty()) one_off += "--preset " + options.preset;
    for (const auto& a : options.assignments) one_off += (one_off.empty() ? "" : ", ") + ("--set " + a);
    if (!options.camera.empty()) one_off += (one_off.empty() ? "" : ", ") + std::string("--camera");
    if (!one_off.empty())
      app.status = "For this run only, not saved unless you change them here: " +
                   shortened(printable(one_off, kFullErrorBytes), kPanelErrorBytes);
    glfwSetWindowUserPointer(window, &app);
    glfwSetDropCallback(window, drop_callback);  // ImGui's backend does not use this one
    try {
      run_loop(app, options, *script);
    } catch (...) {
      glfwSetDropCallback(window, nullptr);
      glfwSetWindowUserPointer(window, nullptr);
      throw;
    }
    glfwSetDropCallback(window, nullptr);
    glfwSetWindowUserPointer(window, nullptr);
    app.settings.keep_camera(app.renderer->scene().name, app.camera);
    app.settings.leave_lab(app.lab->number, app.params);  // on exit
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", one_line_error(e.what()).c_str());
    exit_code = kExitRuntime;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace shadowlab
