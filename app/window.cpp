// The window: one loop in ImGui's order (poll, new frame, input, panel, render, ImGui, swap). What the
// panel shows is app/panel_lab.cpp, the split view and magnifier app/split_view.cpp, the mouse camera
// app/camera_input.cpp, and scripted input for tests app/input_script.cpp; this file wires them up.
#include "app/window.h"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <memory>
#include <optional>

#include "renderer/gl.h"  // before GLFW, so GLFW does not include a GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "app/camera_input.h"
#include "app/headless.h"
#include "app/input_script.h"
#include "app/panel_lab.h"
#include "app/settings_panel.h"
#include "app/split_view.h"
#include "labs/check.h"
#include "labs/lab.h"
#include "renderer/context.h"
#include "renderer/gltf_loader.h"
#include "renderer/image_io.h"
#include "renderer/renderer.h"
#include "renderer/untrusted.h"

namespace shadowlab {

namespace {

// Error texts: at most this much on the terminal, and this much of it in the panel.
constexpr std::size_t kFullErrorBytes = 4000;
constexpr std::size_t kPanelErrorBytes = 480;

constexpr const char* kHeadlessHint =
    "headless commands work without one: shadowlab render --out DIR, shadowlab labs (see --help)";

// Creates the window with the highest core profile the driver gives, 4.6 down to 3.3.
GLFWwindow* create_window() {
  const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}, {4, 1}, {3, 3}};
  for (const auto& v : versions) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, v[0]);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, v[1]);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#ifndef NDEBUG
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
    if (GLFWwindow* w = glfwCreateWindow(1440, 860, "shadowlab", nullptr, nullptr)) return w;
  }
  return nullptr;
}

// The state of one session in the window. Plain members, no statics: the loop below owns it.
struct App {
  GLFWwindow* window = nullptr;
  std::unique_ptr<Renderer> renderer;
  const Lab* lab = nullptr;
  Impl impl = Impl::Exercise;
  ParamSet params;
  OrbitCamera camera;
  std::string lab_text;
  std::string status;       // last screenshot path or error
  std::string scene_error;  // the last dropped file that could not be opened
  bool screenshot_requested = false;
  bool panel_hidden = false;  // H: no ImGui window is built or drawn (the pass-time line stays)
  std::string screenshot_path;  // empty: a timestamped name
  bool check_requested = false;
  std::optional<CheckResult> check_result;  // the last Check, for the current lab and implementation
  double last_poll = 0.0;
  SettingsSession settings;  // each lab's values and the user's presets, kept in the settings file
  CompareState compare;
  SplitView split;
  Magnifier magnifier;
  int windowed[4] = {0, 0, 1440, 860};  // position and size to return to from fullscreen
  std::vector<std::string> dropped;     // files dropped on the window, opened at the next frame
  BenchPanelState bench;                // the Speed against error window
  std::optional<BenchPlots> bench_plots;

  void open_lab(const Lab& next) {
    if (lab) settings.leave_lab(lab->number, params);
    lab = &next;
    check_result.reset();
    params = lab_params(next);
    settings.open_lab(next.number, params);
    lab_text = load_lab_text(next);
    if (compare.with == CompareWith::Preset) compare.preset = 0;
    if (compare.with == CompareWith::OtherImpl && next.exercise_files.empty()) compare.with = CompareWith::Defaults;
    apply_hooks();
  }
  void apply_hooks() {
    if (!renderer->set_lab(lab->hooks(impl))) status = "shader error: the previous program keeps running";
    rebuild_split();
  }
  void rebuild_split() {
    std::string error;
    if (!split.rebuild(*lab, impl, compare, renderer->scene(), &error)) status = "right side: shader error: " + error;
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
      const Scene scene = load_gltf(path);
      renderer->set_scene(scene);
      split.set_scene(scene);
      camera = OrbitCamera::framing(scene.bounds());
      check_result.reset();
      scene_error.clear();
      status = "opened " + printable(path, 200) + " (" + std::to_string(scene.triangle_count()) + " triangles)";
    } catch (const std::exception& e) {
      // The whole message on the terminal; the panel shows a bounded part (ImGui's draw lists hold at
      // most 64k vertices: a 60 MB message made it abort). Loader messages are printable already.
      const std::string full = printable(one_line_error(e.what()), kFullErrorBytes);
      std::fprintf(stderr, "shadowlab: cannot open the dropped file: %s\n", full.c_str());
      scene_error = "Cannot open the dropped file: " + shortened(full, kPanelErrorBytes) + " (the current scene stays)";
    }
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

// Keys, unless ImGui wants the keyboard (typing in a field). ImGui 1.86 indexes keys by GLFW key codes.
void handle_keys(App& app) {
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_F12)) app.screenshot_requested = true;
  if (ImGui::IsKeyPressed(GLFW_KEY_F11, false)) toggle_fullscreen(app);
  for (int n = 0; n <= 9; ++n) {
    const Lab* lab = find_lab(n);
    if (lab && lab != app.lab && ImGui::IsKeyPressed(GLFW_KEY_0 + n, false)) app.open_lab(*lab);
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_N, false) || ImGui::IsKeyPressed(GLFW_KEY_PAGE_DOWN, false))
    app.open_lab(*neighbour_lab(*app.lab, +1));
  if (ImGui::IsKeyPressed(GLFW_KEY_P, false) || ImGui::IsKeyPressed(GLFW_KEY_PAGE_UP, false))
    app.open_lab(*neighbour_lab(*app.lab, -1));
  if (ImGui::IsKeyPressed(GLFW_KEY_S, false)) {
    app.compare.split = !app.compare.split;
    app.rebuild_split();
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_M, false)) app.compare.magnifier = !app.compare.magnifier;
  if (ImGui::IsKeyPressed(GLFW_KEY_H, false)) app.panel_hidden = !app.panel_hidden;
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
  model.check = app.check_result ? &*app.check_result : nullptr;
  model.shader_error = app.renderer->shader_error();
  model.status = app.status;
  model.compare = &app.compare;
  model.settings = &app.settings;
  model.bench = &app.bench;
  model.bench_plots = app.bench_plots ? &*app.bench_plots : nullptr;
  const bool bench_was_open = app.bench.open;
  const PanelActions actions = draw_lab_panel(model);
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
  if (actions.screenshot) app.screenshot_requested = true;
  if (actions.fullscreen) toggle_fullscreen(app);
}

void save_screenshot(App& app, int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  flip_rows(rgba, width, height, 4);
  std::string path = app.screenshot_path;
  if (path.empty()) {
    char name[64];
    const std::time_t now = std::time(nullptr);
    std::strftime(name, sizeof name, "shadowlab-%Y%m%d-%H%M%S.png", std::localtime(&now));
    path = name;
  }
  try {
    write_png(path, width, height, rgba);
    app.status = "saved " + std::filesystem::absolute(path).string();
  } catch (const std::exception& e) {
    app.status = e.what();
  }
}

// One frame of the 3D view: the left (or only) side, the right side of a split, the magnifier's crop,
// and the GPU-time line. ImGui's draw data is rendered after this.
void render_view(App& app, int width, int height) {
  FrameRequest request;
  request.camera = app.camera;
  request.width = width;
  request.height = height;
  app.renderer->render(app.params, request);
  app.renderer->present(0, width, height);
  if (app.compare.split)
    app.split.compose(app.split.right_params(*app.lab, app.params, app.compare), request, app.compare, *app.lab, app.impl);
  if (app.compare.magnifier) {
    app.magnifier.capture(width, height);
    app.magnifier.draw();
  }
  draw_pass_overlay(app.renderer->stats(), app.compare.split ? app.split.stats() : nullptr);
}

void drop_callback(GLFWwindow* window, int count, const char** paths) {
  auto* app = static_cast<App*>(glfwGetWindowUserPointer(window));
  for (int i = 0; app && i < count; ++i) app->dropped.emplace_back(paths[i]);
}

void run_loop(App& app, const WindowOptions& options, InputScript& script) {
  int frame = 0;
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
      app.settings.autosave(app.lab->number, app.params);
    }
    if (!app.panel_hidden) draw_panel(app);
    if (app.check_requested) {
      app.check_result = run_lab_check(*app.lab, app.impl, app.renderer->scene());
      app.check_requested = false;
    }
    render_view(app, width, height);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
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
    if (last_frame) glfwSetWindowShouldClose(app.window, GLFW_TRUE);
  }
}

}  // namespace

int run_window(const WindowOptions& options) {
  const Lab* lab = find_lab(options.lab);
  if (!lab) {
    std::fprintf(stderr, "shadowlab: no lab %d (see `shadowlab labs`)\n", options.lab);
    return 2;
  }
  std::optional<InputScript> script;
  try {
    script.emplace(options.script);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return 2;
  }
  Scene scene;
  try {
    scene = load_scene_or_default(options.scene_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", one_line_error(e.what()).c_str());
    return 1;
  }
  std::optional<BenchPlots> bench;  // asked for on the command line: read it now, or say why not
  try {
    if (!options.bench_file.empty()) bench = load_bench_plots(options.bench_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", e.what());
    return 1;
  }
  if (!glfwInit()) {
    std::fprintf(stderr, "shadowlab: no display to open a window on (DISPLAY is not set); %s\n", kHeadlessHint);
    return 1;
  }
  GLFWwindow* window = create_window();
  if (!window) {
    std::fprintf(stderr, "shadowlab: cannot create an OpenGL 3.3 core window; %s\n", kHeadlessHint);
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
#ifndef NDEBUG
  enable_gl_debug_output();
#endif

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // window layout is not worth a file in the user's folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  try {
    App app;
    app.window = window;
    app.renderer = std::make_unique<Renderer>();
    app.renderer->set_scene(scene);
    app.camera = OrbitCamera::framing(scene.bounds());
    app.bench.path = options.bench_file.empty() ? (data_dir() / "docs" / "bench.json").string() : options.bench_file;
    app.bench_plots = std::move(bench);
    app.bench.open = app.bench_plots.has_value();
    app.settings.start();  // only now: a run that failed to start never touches the settings file
    app.open_lab(*lab);
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
    app.settings.leave_lab(app.lab->number, app.params);  // on exit
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab: %s\n", one_line_error(e.what()).c_str());
    exit_code = 1;
  }
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace shadowlab
