#include "app/window.h"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "renderer/gl.h"  // before GLFW, so GLFW does not include a GL header of its own
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "app/headless.h"
#include "app/panel.h"
#include "app/settings_panel.h"
#include "labs/check.h"
#include "labs/lab.h"
#include "renderer/context.h"
#include "renderer/image_io.h"
#include "renderer/renderer.h"

namespace shadowlab {

namespace {

constexpr const char* kHeadlessHint =
    "headless commands work without one: shadowlab render --out DIR, shadowlab labs (see --help)";

std::string read_file_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Lab texts are Markdown hard-wrapped at 100 columns; the panel wraps by itself, so join the lines of
// each paragraph. Headings, list items, indented code and table rows keep their own lines.
std::string reflow_markdown(const std::string& text) {
  std::istringstream in(text);
  std::string out, line;
  bool joinable = false;  // the previous line was paragraph text
  while (std::getline(in, line)) {
    const bool blank = line.find_first_not_of(' ') == std::string::npos;
    const bool structural = !blank && (line[0] == '#' || line[0] == '|' || line.rfind("    ", 0) == 0 ||
                                       line.rfind("- ", 0) == 0 || (std::isdigit(static_cast<unsigned char>(line[0])) &&
                                                                    line.find(". ") < 4));
    const bool continuation = !blank && !structural && line[0] == ' ';
    if (joinable && !blank && (!structural || continuation)) {
      out += ' ' + line.substr(line.find_first_not_of(' '));
    } else {
      if (!out.empty()) out += '\n';
      out += line;
    }
    joinable = !blank && line[0] != '#' && line[0] != '|' && line.rfind("    ", 0) != 0;
  }
  return out;
}

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
  std::string status;  // last screenshot path or error
  bool screenshot_requested = false;
  bool check_requested = false;
  std::optional<CheckResult> check_result;  // the last Check, for the current lab and implementation
  double last_poll = 0.0;
  SettingsSession settings;  // each lab's values and the user's presets, kept in the settings file

  void open_lab(const Lab& next) {
    if (lab) settings.leave_lab(lab->number, params);
    lab = &next;
    check_result.reset();
    params = lab_params(next);
    settings.open_lab(next.number, params);
    lab_text = reflow_markdown(read_file_text(next.text_path()));
    apply_hooks();
  }
  void apply_hooks() {
    if (!renderer->set_lab(lab->hooks(impl))) status = "shader error: the previous program keeps running";
  }
};

void draw_check_result(const CheckResult& r) {
  const ImVec4 green(0.45f, 0.85f, 0.45f, 1.0f), red(1.0f, 0.45f, 0.4f, 1.0f);
  ImGui::TextColored(r.passed() ? green : red, "%s (%.1f s)", r.passed() ? "PASS" : "FAIL", r.seconds);
  if (!r.error.empty()) ImGui::TextColored(red, "%s", r.error.c_str());
  for (const auto& c : r.criteria) {
    ImGui::TextColored(c.passed() ? green : red, "%s %s = %.4g %s %.4g", c.passed() ? "ok  " : "FAIL", c.metric.c_str(),
                       c.value, c.direction == Criterion::kAtMost ? "<=" : ">=", c.limit);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.why.c_str());
  }
}

// Runs the lab's check in this window's GL context, with a renderer of its own (offscreen targets),
// exactly as `shadowlab check` does headless.
void run_check(App& app) {
  CheckResult result;
  result.lab = app.lab->number;
  result.slug = app.lab->slug;
  result.impl = app.impl;
  const auto start = std::chrono::steady_clock::now();
  try {
    Renderer renderer;
    CheckContext ctx(renderer, *app.lab, app.impl, app.renderer->scene(), {});
    app.lab->check(ctx, result);
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  app.check_result = result;
}

void draw_panel(App& app) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 700), ImGuiCond_FirstUseEver);
  ImGui::Begin("shadowlab");
  if (ImGui::BeginCombo("Lab", (std::to_string(app.lab->number) + "  " + app.lab->title).c_str())) {
    for (const auto& lab : all_labs()) {
      if (ImGui::Selectable((std::to_string(lab.number) + "  " + lab.title).c_str(), &lab == app.lab)) app.open_lab(lab);
    }
    ImGui::EndCombo();
  }
  if (!app.lab->exercise_files.empty()) {
    int impl = app.impl == Impl::Exercise ? 0 : 1;
    bool changed = ImGui::RadioButton("Exercise", &impl, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("Solution", &impl, 1);
    if (changed) {
      app.impl = impl == 0 ? Impl::Exercise : Impl::Solution;
      app.check_result.reset();
      app.apply_hooks();
    }
  }
  if (ImGui::CollapsingHeader("Lab text", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(app.lab_text.c_str());
    ImGui::PopTextWrapPos();
  }
  if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) {
    param_widgets(app.params);
    if (ImGui::Button("Defaults")) app.params.reset_to_defaults();
    for (const auto& preset : app.lab->presets) {
      ImGui::SameLine();
      if (ImGui::Button(preset.name.c_str())) {
        for (const auto& [key, value] : preset.values) app.params.set_from_string(key, value);
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", preset.description.c_str());
    }
    app.settings.draw_presets(app.lab->number, app.params);
  }
  if (ImGui::CollapsingHeader("GPU time per pass", ImGuiTreeNodeFlags_DefaultOpen)) {
    const FrameStats& stats = app.renderer->stats();
    for (const auto& p : stats.passes) ImGui::Text("%-12s %7.2f ms", p.name.c_str(), p.gpu_ms);
    ImGui::Text("shadow passes run: %ld of %ld frames", stats.shadow_passes, stats.frames);
    ImGui::Text("%zu triangles", app.renderer->scene().triangle_count());
  }
  const std::string error = app.renderer->shader_error();
  if (!error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("Shader error (the last good program keeps running):\n%s", error.c_str());
    ImGui::PopStyleColor();
  }
  if (app.lab->check && ImGui::CollapsingHeader("Check", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (ImGui::Button("Check")) app.check_requested = true;
    ImGui::SameLine();
    ImGui::TextDisabled("same as: shadowlab check --lab %d --impl %s", app.lab->number, impl_name(app.impl));
    if (app.check_result) draw_check_result(*app.check_result);
  }
  if (ImGui::Button("Screenshot (F12)")) app.screenshot_requested = true;
  if (!app.status.empty()) ImGui::TextWrapped("%s", app.status.c_str());
  ImGui::End();
}

void handle_camera_input(App& app) {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureMouse) return;
  if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    app.camera.yaw_deg -= io.MouseDelta.x * 0.3f;
    app.camera.pitch_deg = std::clamp(app.camera.pitch_deg + io.MouseDelta.y * 0.3f, -85.0f, 85.0f);
  }
  if (io.MouseWheel != 0.0f) app.camera.distance *= std::pow(0.9f, io.MouseWheel);
}

void save_screenshot(App& app, int width, int height, std::string path) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  flip_rows(rgba, width, height, 4);
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

}  // namespace

int run_window(const WindowOptions& options) {
  const Lab* lab = find_lab(options.lab);
  if (!lab) {
    std::fprintf(stderr, "shadowlab: no lab %d (see `shadowlab labs`)\n", options.lab);
    return 2;
  }
  Scene scene;
  try {
    scene = load_scene_or_default(options.scene_file);
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
    app.settings.start();  // only now: a run that failed to start never touches the settings file
    app.open_lab(*lab);

    int frame = 0;
    while (!glfwWindowShouldClose(window)) {
      glfwPollEvents();
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      if (width == 0 || height == 0) {  // minimised: nothing to draw
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      handle_camera_input(app);
      if (!ImGui::GetIO().WantCaptureKeyboard && ImGui::IsKeyPressed(GLFW_KEY_F12)) app.screenshot_requested = true;  // 1.86: GLFW key codes
      // Students' edits to shader files reload live; checking twice a second is plenty.
      if (glfwGetTime() - app.last_poll > 0.5) {
        app.renderer->poll_shader_files();
        app.last_poll = glfwGetTime();
        app.settings.autosave(app.lab->number, app.params);
      }
      draw_panel(app);

      if (app.check_requested) {
        run_check(app);
        app.check_requested = false;
      }
      FrameRequest request;
      request.camera = app.camera;
      request.width = width;
      request.height = height;
      app.renderer->render(app.params, request);
      app.renderer->present(0, width, height);
      ImGui::Render();
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      ++frame;
      const bool last_frame = options.frames > 0 && frame >= options.frames;
      if (app.screenshot_requested || (last_frame && !options.screenshot.empty())) {
        save_screenshot(app, width, height, last_frame ? options.screenshot : std::string());
        app.screenshot_requested = false;
      }
      glfwSwapBuffers(window);
      if (last_frame) glfwSetWindowShouldClose(window, GLFW_TRUE);
    }
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
