// The window: one loop in ImGui's order (poll, new frame, input, panel, render, ImGui, swap), its keys and
// its start. The session's state and what it does is app/window_app.{h,cpp}, the Check's worker
// app/window_check_worker.cpp, screenshots and texts over the view app/window_overlays.cpp; what the
// panel shows is app/panel_lab.cpp, the split view and magnifier app/split_view.cpp, the mouse camera
// app/camera_input.cpp, and scripted input for tests app/input_script.cpp.
#include "app/window.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

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
#include "app/window_app.h"
#include "grading/check.h"
#include "grading/cpp_exercise.h"
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

constexpr const char* kHeadlessHint =
    "headless commands work without one: shadowlab render --out DIR, shadowlab labs (see --help)";

void toggle_fullscreen(WindowApp& app) {
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
void handle_keys(WindowApp& app) {
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

// Fonts and style for the window's monitor and the user's text size; rebuilt (between frames) when
// either changes, e.g. when the window moves to a monitor with another scale.
void update_ui_scale(WindowApp& app) {
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

void draw_panel(WindowApp& app) {
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
  model.cpp_status = app.live_cpp.message();
  model.cpp_error = app.live_cpp.has_error();
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

// One frame of the 3D view: the left (or only) side, the right side of a split, the magnifier's crop,
// and the GPU-time line. ImGui's draw data is rendered after this.
void render_view(WindowApp& app, int width, int height) {
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

  static long finishes(const WindowApp& app) {
    const FrameStats* right = app.split.stats();
    return app.renderer->stats().gl_finishes + (right ? right->gl_finishes : 0);
  }
  static long blocking(const WindowApp& app) {
    const FrameStats* right = app.split.stats();
    return app.renderer->stats().blocking_query_reads + (right ? right->blocking_query_reads : 0);
  }
  void write(const std::string& path, const WindowApp& app) const {
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
  auto* app = static_cast<WindowApp*>(glfwGetWindowUserPointer(window));
  for (int i = 0; app && i < count; ++i) app->dropped.emplace_back(paths[i]);
}

// A Check that finished on the worker: its time kept for the progress bar, its result shown when it is
// still for the lab and implementation on screen.
void take_live_hooks(WindowApp& app) {
  if (std::optional<Features> hooks = app.live_cpp.take_hooks()) app.use_live_hooks(*hooks);
}

void take_finished_check(WindowApp& app) {
  if (auto result = app.check_worker.take_result()) {
    const Lab* checked = app.check_worker.lab();
    app.check_seconds[result->lab] = result->seconds;
    if (checked == app.lab && result->impl == app.impl) app.check_result = std::move(result);
  }
}

// Students' edits to shader files reload live; checking twice a second is plenty. The camera and the
// lab's values are saved on the same beat.
void poll_files(WindowApp& app) {
  if (glfwGetTime() - app.last_poll <= 0.5) return;
  app.renderer->poll_shader_files();
  app.split.poll_shader_files();
  // A saved C++ exercise is built again on a worker thread; its hooks are used once they are ready. What
  // it says is also said on the terminal, once (a build error in full there).
  app.live_cpp.poll(*app.lab, app.impl);
  if (const std::string said = app.live_cpp.message(); said != app.live_cpp_said) {
    if (!said.empty()) std::fprintf(app.live_cpp.has_error() ? stderr : stdout, "shadowlab: %s\n", said.c_str());
    std::fflush(stdout);
    app.live_cpp_said = said;
  }
  app.last_poll = glfwGetTime();
  app.settings.keep_camera(app.renderer->scene().name, app.camera);
  app.settings.autosave(app.lab->number, app.params);
}

// What the panel, the keys or the script asked for this frame, done before the view is drawn.
void run_requests(WindowApp& app, InputScript& script, int width, int height) {
  if (script.take_check_request()) app.check_requested = true;
  if (script.take_solution_beside_request()) app.show_solution_beside();
  if (app.penumbra_requested) {
    app.measure_penumbra(width, height);
    app.penumbra_requested = false;
  }
  if (app.check_requested) {
    std::string error;
    if (!app.check_worker.start(*app.lab, app.impl, app.renderer->scene(), app.scene_from_file, &error)) app.status = error;
    app.check_requested = false;
  }
}

// The view, counted on the side of the frame report it belongs to (pass-time line shown or hidden).
void render_counted_view(WindowApp& app, FrameCost& cost, int width, int height, double since_last_frame) {
  // The pass-time line decides how passes are timed: for nothing, where it is not shown and the
  // driver's timer queries are useless; never by waiting for the GPU where they work.
  const TimingMode timing = interactive_timing(app.renderer->timers_work(), app.pass_line_shown());
  app.renderer->set_timing(timing);
  app.split.set_timing(timing);
  // The flashlight's node circles the scene while flashlight.animate is on (only its map is redrawn).
  if (app.params.get(param::flashlight_animate))
    app.params.set("flashlight.phase", advance_flashlight_phase(app.params, since_last_frame));
  const long finishes_before = FrameCost::finishes(app), blocking_before = FrameCost::blocking(app);
  render_view(app, width, height);
  FrameCost::Side& side = app.pass_line_shown() ? cost.shown : cost.hidden;
  ++side.frames;
  side.gl_finishes += FrameCost::finishes(app) - finishes_before;
  side.blocking_reads += FrameCost::blocking(app) - blocking_before;
}

void run_loop(WindowApp& app, const WindowOptions& options, InputScript& script) {
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
    take_finished_check(app);
    take_live_hooks(app);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (!app.split.handle_divider(app.compare)) orbit_pan_zoom(app.camera, app.renderer->scene().bounds());
    handle_keys(app);
    poll_files(app);
    if (!app.panel_hidden) draw_panel(app);
    else draw_hidden_hint(app);
    draw_caption(app);
    draw_toast(app);
    run_requests(app, script, width, height);
    try {
      render_counted_view(app, cost, width, height, glfwGetTime() - frame_start);
    } catch (const ExerciseError& e) {  // the edited C++ exercise's program crashed or timed out on a call
      app.apply_hooks(false);  // the compiled copy again (not the failed build once more)
      app.live_cpp.failed(e.what());
    }
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

// What the command line asks of the window, read and checked before any window opens.
struct StartValues {
  std::optional<InputScript> script;
  Scene scene;
  const Preset* preset = nullptr;
  int width = 1440, height = 860;
  OrbitCamera camera;
  std::optional<BenchPlots> bench;  // asked for on the command line: read now, or said why not
};

// Reads the options into `v`; on a bad one says why and returns false (a usage error).
bool read_start_values(const WindowOptions& options, const Lab& lab, StartValues& v) {
  ParamSet check = lab_params(lab);
  try {
    v.script.emplace(options.script);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return false;
  }
  try {
    v.preset = apply_preset_option(check, lab, options.preset);
    v.scene = scene_option(options.scene_file, v.preset);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", one_line_error(e.what()).c_str());
    return false;
  }
  try {
    if (!options.size.empty()) parse_size_option(options.size, &v.width, &v.height);
    for (const auto& a : options.assignments) apply_set_option(check, a);
    v.camera = view_camera(options.camera, v.preset, v.scene, check);
    if (!options.bench_file.empty()) v.bench = load_bench_plots(options.bench_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return false;
  }
  return true;
}

// The session's start: renderer, scene, camera, saved settings, then the lab with --preset and --set over
// its saved values (shown in this run, saved only if changed in the window).
void start_session(WindowApp& app, const WindowOptions& options, const Lab& lab, StartValues& v) {
  app.gl_summary = gl_summary();
  app.gl_fallbacks = gl_fallbacks();
  app.renderer = std::make_unique<Renderer>();
  app.renderer->set_scene(v.scene);
  app.scene_from_file = !options.scene_file.empty();
  app.camera = v.camera;
  app.windowed[2] = v.width;
  app.windowed[3] = v.height;
  app.bench.path = options.bench_file.empty() ? (data_dir() / "docs" / "bench.json").string() : options.bench_file;
  app.bench_plots = std::move(v.bench);
  app.bench.open = app.bench_plots.has_value();
  app.impl = options.impl == "solution" ? Impl::Solution : Impl::Exercise;  // never saved: one-off as it is
  app.settings.start();  // only now: a run that failed to start never touches the settings file
  if (const auto size = app.settings.text_size()) app.text_size = *size;
  // The camera kept for this scene, unless --camera or the preset's view chose one (for this run: kept once
  // the user moves it).
  if (options.camera.empty() && (!v.preset || v.preset->view.camera.empty())) {
    if (const auto kept = app.settings.camera(v.scene.name)) app.camera = *kept;
  } else {
    app.settings.give_one_off_camera(v.camera);
  }
  app.open_lab(lab, true);  // the first frame draws the student's GL exercise (built before it)
  const ParamSet saved = app.params;
  apply_preset_option(app.params, lab, options.preset);
  for (const auto& a : options.assignments) apply_set_option(app.params, a);
  app.settings.give_one_off(lab.number, saved, app.params);
  // Said in the panel, so that a value missing at the next start is no surprise.
  std::string one_off;
  if (!options.preset.empty()) one_off += "--preset " + options.preset;
  for (const auto& a : options.assignments) one_off += (one_off.empty() ? "" : ", ") + ("--set " + a);
  if (!options.camera.empty()) one_off += (one_off.empty() ? "" : ", ") + std::string("--camera");
  if (!one_off.empty())
    app.status = "For this run only, not saved unless you change them here: " +
                 shortened(printable(one_off, kFullErrorBytes), kPanelErrorBytes);
}

// The session in `window`, from its start to its end; the settings kept on exit.
void run_session(GLFWwindow* window, const WindowOptions& options, const Lab& lab, StartValues& v) {
  WindowApp app;
  app.window = window;
  start_session(app, options, lab, v);
  glfwSetWindowUserPointer(window, &app);
  glfwSetDropCallback(window, drop_callback);  // ImGui's backend does not use this one
  try {
    run_loop(app, options, *v.script);
  } catch (...) {
    glfwSetDropCallback(window, nullptr);
    glfwSetWindowUserPointer(window, nullptr);
    throw;
  }
  glfwSetDropCallback(window, nullptr);
  glfwSetWindowUserPointer(window, nullptr);
  app.settings.keep_camera(app.renderer->scene().name, app.camera);
  app.settings.leave_lab(app.lab->number, app.params);  // on exit
}

}  // namespace

int run_window(const WindowOptions& options) {
  const Lab* lab = find_lab(options.lab);
  if (!lab) {
    std::fprintf(stderr, "shadowlab: no lab %d (see `shadowlab labs`)\n", options.lab);
    return kExitUsage;
  }
  StartValues start;
  if (!read_start_values(options, *lab, start)) return kExitUsage;
  capture_glfw_errors();
  if (!glfwInit()) {
    std::fprintf(stderr, "shadowlab: cannot open a window: %s; %s\n", take_glfw_error().c_str(), kHeadlessHint);
    return kExitRuntime;
  }
  GLFWwindow* window = create_window(true, start.width, start.height);
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
    run_session(window, options, *lab, start);
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
