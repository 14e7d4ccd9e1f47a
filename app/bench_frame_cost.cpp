#include "app/bench_frame_cost.h"

#include <chrono>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "app/bench_baseline.h"
#include "app/bench_figures.h"
#include "app/imgui_offscreen.h"
#include "app/panel_lab.h"
#include "labs/registry.h"
#include "renderer/gl_objects.h"

namespace shadowlab {

FrameRequest bench_request(const Bounds& view) {
  FrameRequest request;
  request.camera = OrbitCamera::framing(view);
  request.width = kBenchWidth;
  request.height = kBenchHeight;
  return request;
}

const Lab& blurred_moments_lab() {
  for (const auto& lab : all_labs())
    if (lab.hooks(Impl::Solution).technique == ShadowTechnique::Moments && lab_params(lab).find("vsm.blur_radius"))
      return lab;
  throw std::runtime_error("no lab stores blurred moments: the bench's skipping, overlay and blur figures need one");
}

// Steady frame cost of an orbiting camera under a still light, with the renderer skipping the shadow
// pass (as it does) and forced to redo it every frame; against the lit pass alone. The frame cost is the
// wall time of the whole render() call (every pass is finished inside it), so the skipping's own
// bookkeeping counts too.
nlohmann::json measure_skipping(Renderer& renderer, const Scene& scene, int frames) {
  const Lab& lab = blurred_moments_lab();
  ParamSet params = lab_params(lab);
  params.set_from_string("vsm.blur_radius", "4");
  params.set("view.debug_quad", 0.0);
  renderer.set_features(lab.hooks(Impl::Solution));
  renderer.set_scene(scene);
  FrameRequest request = bench_request(scene.bounds());
  auto run = [&](bool force) {
    std::vector<double> total, lit;
    const long shadow_before = renderer.stats().shadow_passes;
    for (int f = 0; f < frames; ++f) {
      request.camera.yaw_deg += 360.0f / static_cast<float>(frames);
      if (force) renderer.invalidate_shadow_map();
      const FrameStats& stats = renderer.render(params, request);
      for (const auto& p : stats.passes)
        if (p.name == "lit") lit.push_back(p.gpu_ms);
      total.push_back(stats.cpu_ms);
    }
    return std::tuple{median(total), median(lit), renderer.stats().shadow_passes - shadow_before};
  };
  run(true);  // warm-up
  const auto [skip_total, skip_lit, skip_shadow] = run(false);
  const auto [force_total, force_lit, force_shadow] = run(true);
  return {{"frames", frames},
          {"with_skipping_ms", skip_total},
          {"without_skipping_ms", force_total},
          {"lit_pass_ms", skip_lit},
          {"ratio_to_lit_pass", skip_lit > 0 ? skip_total / skip_lit : 0.0},
          {"shadow_passes_with_skipping", skip_shadow},
          {"shadow_passes_without_skipping", force_shadow}};
}

void print_skipping(const nlohmann::json& skipping) {
  std::printf("steady frame with skipping: %.2f ms = %.2f x the lit pass alone (%.2f ms); without skipping %.2f ms\n",
              skipping["with_skipping_ms"].get<double>(), skipping["ratio_to_lit_pass"].get<double>(),
              skipping["lit_pass_ms"].get<double>(), skipping["without_skipping_ms"].get<double>());
}

// What the views cost when shown, and that hiding them removes them: the debug quads (VSM: three) and
// the light volume's wireframe are passes of their own (absent when hidden); the panel is ImGui, timed
// offscreen building and drawing it (3 layout frames + 1 draw + a read-back per call, as `render --panel`
// does) against the same call with no window in it.
nlohmann::json measure_overlays(Renderer& renderer, const Scene& scene, int frames) {
  const Lab& lab = blurred_moments_lab();
  renderer.set_features(lab.hooks(Impl::Solution));
  renderer.set_scene(scene);
  FrameRequest request = bench_request(scene.bounds());
  auto pass_median = [&](ParamSet params, const char* name, long* present) {
    std::vector<double> ms;
    *present = 0;
    for (int f = 0; f < frames; ++f) {
      for (const auto& p : renderer.render(params, request).passes)
        if (p.name == name) ms.push_back(p.gpu_ms), ++*present;
    }
    return median(ms);
  };
  ParamSet shown = lab_params(lab);
  shown.set("view.debug_quad", 1.0);
  shown.set("view.light_volume", 1.0);
  ParamSet hidden = shown;
  hidden.set("view.debug_quad", 0.0);
  hidden.set("view.light_volume", 0.0);
  long quad_frames = 0, volume_frames = 0, quad_hidden = 0, volume_hidden = 0;
  const double quad_ms = pass_median(shown, "debug_quad", &quad_frames);
  const double volume_ms = pass_median(shown, "light_volume_view", &volume_frames);
  pass_median(hidden, "debug_quad", &quad_hidden);
  pass_median(hidden, "light_volume_view", &volume_hidden);
  std::vector<double> lit_ms;
  for (int f = 0; f < frames; ++f)
    for (const auto& p : renderer.render(hidden, request).passes)
      if (p.name == "lit") lit_ms.push_back(p.gpu_ms);

  const LabText text = load_lab_text(lab);
  PanelModel model;
  model.lab = &lab;
  model.params = &shown;
  model.stats = &renderer.stats();
  model.triangles = scene.triangle_count();
  model.scene_name = scene.name;
  model.lab_text = &text;
  model.interactive = false;
  ImGuiOffscreen imgui(kBenchWidth, kBenchHeight);
  auto time_ui = [&](const std::function<void()>& draw) {
    std::vector<double> ms;
    for (int f = 0; f < frames; ++f) {
      const auto start = std::chrono::steady_clock::now();
      imgui.render(draw);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return median(ms);
  };
  time_ui([&] { draw_lab_panel(model); });  // warm-up: fonts, shaders
  const double panel_ms = time_ui([&] { draw_lab_panel(model); });
  const double no_panel_ms = time_ui([] {});
  return {{"frames", frames},
          {"lit_pass_ms", median(lit_ms)},
          {"debug_quad_ms", quad_ms},
          {"debug_quad_passes_shown", quad_frames},
          {"debug_quad_passes_hidden", quad_hidden},
          {"light_volume_ms", volume_ms},
          {"light_volume_passes_shown", volume_frames},
          {"light_volume_passes_hidden", volume_hidden},
          {"panel_ui_ms", panel_ms},
          {"no_panel_ui_ms", no_panel_ms}};
}

void print_overlays(const nlohmann::json& overlays) {
  std::printf("views: debug quads %.2f ms, light volume %.2f ms (lit pass %.2f ms); hidden: %ld and %ld passes in %d "
              "frames; panel %.2f ms per offscreen build+draw vs %.2f ms with it hidden\n",
              overlays["debug_quad_ms"].get<double>(), overlays["light_volume_ms"].get<double>(),
              overlays["lit_pass_ms"].get<double>(), overlays["debug_quad_passes_hidden"].get<long>(),
              overlays["light_volume_passes_hidden"].get<long>(), overlays["frames"].get<int>(),
              overlays["panel_ui_ms"].get<double>(), overlays["no_panel_ui_ms"].get<double>());
}

namespace {

constexpr int kW = 1280, kH = 720;  // the frame-cost figure's frame

// A framebuffer standing for the window: kW x kH colour and depth-stencil.
struct WindowStandIn {
  GlTexture color = make_texture_2d(GL_RGBA8, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR);
  GlRenderbuffer depth = GlRenderbuffer::create();
  GlFramebuffer window = GlFramebuffer::create();
  WindowStandIn() {
    glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kW, kH);
    glBindFramebuffer(GL_FRAMEBUFFER, window.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth.id());
    check_framebuffer("the bench's window stand-in");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
};

template <typename Draw>
double wall(const Draw& draw) {
  const auto start = std::chrono::steady_clock::now();
  draw();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

ParamSet lab_setup(Renderer& renderer, const Lab& lab) {
  ParamSet params = lab_params(lab);
  params.set_from_string("light.azimuth", "153.43");   // toward (-2, 4, -1)
  params.set_from_string("light.elevation", "60.79");
  params.set_from_string("shadow.map_size", "1024");
  params.set("view.debug_quad", 0.0);
  if (!renderer.set_features(lab.hooks(Impl::Solution))) throw std::runtime_error(renderer.shader_error());
  return params;
}

// One lab's whole frame (no timing, into the window stand-in) and each of its passes alone (Exact).
void frame_and_passes(Renderer& renderer, const FrameRequest& request, int frames, const ParamSet& params,
                      std::vector<double>* frame_ms, std::map<std::string, std::vector<double>>* pass_ms) {
  renderer.set_timing(TimingMode::Exact);
  for (int f = 0; f < 2; ++f) renderer.render(params, request);  // warm-up: programs, targets, the map
  for (int f = 0; f < frames; ++f) {
    renderer.set_timing(TimingMode::Off);
    frame_ms->push_back(wall([&] { renderer.render(params, request); }));
    renderer.set_timing(TimingMode::Exact);
    for (const auto& p : renderer.render(params, request).passes) (*pass_ms)[std::string(p.name)].push_back(p.gpu_ms);
  }
}

// Every lab's whole frame (the same way) against its lit pass alone (Exact timing).
nlohmann::json every_lab_frame(Renderer& renderer, const FrameRequest& request, int frames) {
  nlohmann::json labs = nlohmann::json::array();
  for (const auto& lab : all_labs()) {
    const ParamSet lp = lab_setup(renderer, lab);
    std::vector<double> frame_ms;
    std::map<std::string, std::vector<double>> pass_ms;
    frame_and_passes(renderer, request, frames, lp, &frame_ms, &pass_ms);
    const double frame = median(frame_ms), lit = median(pass_ms["lit"]);
    // Shadow volumes light the view in passes of their own every frame (the scene with ambient light,
    // the volumes into the stencil, then the lit pass adding the light where no volume counted): the
    // stencil is the shadow test, done in the view, so it depends on the camera as well as the light.
    nlohmann::json passes = nlohmann::json::object();
    double view_passes = 0.0;
    for (auto& [name, ms] : pass_ms) {
      passes[name] = median(ms);
      if (name == "ambient" || name == "volumes" || name == "lit") view_passes += median(ms);
    }
    labs.push_back({{"lab", lab.number}, {"frame_ms", frame}, {"lit_pass_ms", lit}, {"ratio_to_lit_pass", lit > 0 ? frame / lit : 0.0},
                    {"passes_ms", passes}, {"view_passes_ms", view_passes},
                    {"ratio_to_view_passes", view_passes > 0 ? frame / view_passes : 0.0}});
  }
  return labs;
}

}  // namespace

// The lab's windowed-path frame against the bare two-pass baseline (app/bench_baseline.h), side by side
// in one run: LearnOpenGL's scene, light direction ((-2, 4, -1) toward the origin) and camera (at
// (0, 0, 3) looking down -z, 45 degrees), 1280 x 720, 1024^2 map. The lab's frame is what the window
// draws with the panel hidden and a still light: straight into a framebuffer standing for the window,
// no timing (TimingMode::Off), the shadow pass skipped; the baseline redraws its map every frame, as
// the tutorial does. Each frame is the wall time from the first call to a glFinish after the last, the
// two alternating frame by frame. Then every lab's whole frame (the same way) against its lit pass
// alone (Exact timing).
nlohmann::json measure_frame_cost(Renderer& renderer, int frames) {
  const Scene scene = make_learnopengl_scene();
  renderer.set_scene(scene);
  const WindowStandIn stand_in;
  const GlFramebuffer& window = stand_in.window;

  FrameRequest request;
  request.camera = OrbitCamera::looking({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 2.0f}, 45.0f, scene.bounds());
  request.width = kW;
  request.height = kH;
  request.to_window = true;
  request.window_framebuffer = window.id();

  // PCF 3x3 (the renderer's default kernel), drawn by the lab that offers it to the bench.
  const Lab* pcf = find_lab_offering("pcf 3");
  if (!pcf) throw std::runtime_error("the frame-cost figure needs a lab offering \"pcf 3\" to the bench (PCF, 3 x 3)");
  ParamSet params = lab_setup(renderer, *pcf);
  renderer.set_timing(TimingMode::Off);
  renderer.set_lit_constants(false);  // warm-up: both lit programs built before anything is timed
  renderer.render(params, request);
  renderer.set_lit_constants(true);
  renderer.render(params, request);
  BareTwoPass bare(scene, 1024);
  const glm::mat4 light_vp = renderer.light_view().projection * renderer.light_view().view;
  const glm::mat4 camera_vp = renderer.camera_projection() * renderer.camera_view();
  auto bare_frame = [&] { bare.draw(light_vp, renderer.to_light(), camera_vp, window.id(), kW, kH); };
  for (int f = 0; f < 2; ++f) wall(bare_frame);
  // What each of issue 17's changes saved, in the same run: the frame as the window drew it before
  // (every pass finished and its query read, drawn offscreen and copied), then without the copy.
  FrameRequest offscreen = request;
  offscreen.to_window = false;
  // And with the generic lit program (PCF's kernel and comparison read as uniforms, as before).
  std::vector<double> lab_ms, bare_ms, exact_ms, before_ms, generic_ms;
  for (int f = 0; f < frames; ++f) {
    renderer.set_timing(TimingMode::Off);
    lab_ms.push_back(wall([&] { renderer.render(params, request); }));
    bare_ms.push_back(wall(bare_frame));
    renderer.set_lit_constants(false);
    generic_ms.push_back(wall([&] { renderer.render(params, request); }));
    renderer.set_lit_constants(true);
    renderer.set_timing(TimingMode::Exact);
    exact_ms.push_back(wall([&] { renderer.render(params, request); }));
    before_ms.push_back(wall([&] {
      renderer.render(params, offscreen);
      renderer.present(window.id(), kW, kH);
    }));
  }
  const nlohmann::json labs = every_lab_frame(renderer, request, frames);
  renderer.set_timing(TimingMode::Exact);
  const double lab_frame = median(lab_ms), bare_frame_ms = median(bare_ms);
  return {{"frames", frames},
          {"size", {kW, kH}},
          {"lab6_frame_ms", lab_frame},
          {"lab6_frame_generic_program_ms", median(generic_ms)},
          {"lab6_frame_exact_timing_ms", median(exact_ms)},
          {"lab6_frame_exact_timing_copied_ms", median(before_ms)},
          {"bare_two_pass_ms", bare_frame_ms},
          {"ratio_to_bare", bare_frame_ms > 0 ? lab_frame / bare_frame_ms : 0.0},
          {"labs", labs}};
}

void print_frame_cost(const nlohmann::json& frame_cost) {
  std::printf("frame cost, lab 6 at LearnOpenGL's view, 1280x720, panel hidden, still light: %.2f ms = %.2fx the bare "
              "two-pass baseline (%.2f ms; done when <= 1.1x); with the generic lit program (PCF's settings as uniforms): "
              "%.2f ms; with every pass finished and timed: %.2f ms; and drawn offscreen and copied (the window before "
              "issue 17): %.2f ms\n",
              frame_cost["lab6_frame_ms"].get<double>(), frame_cost["ratio_to_bare"].get<double>(),
              frame_cost["bare_two_pass_ms"].get<double>(), frame_cost["lab6_frame_generic_program_ms"].get<double>(),
              frame_cost["lab6_frame_exact_timing_ms"].get<double>(),
              frame_cost["lab6_frame_exact_timing_copied_ms"].get<double>());
  for (const auto& l : frame_cost["labs"]) {
    const auto& passes = l["passes_ms"];
    if (!passes.contains("volumes")) {
      std::printf("frame cost, lab %d: whole frame %.2f ms = %.2fx its lit pass (%.2f ms; done when <= 1.15x)\n",
                  l["lab"].get<int>(), l["frame_ms"].get<double>(), l["ratio_to_lit_pass"].get<double>(),
                  l["lit_pass_ms"].get<double>());
      continue;
    }
    // Shadow volumes draw their lit image in three passes every frame, all in the camera's view (the
    // stencil is the shadow test): the done-when's "lit pass" is those three; the additive pass alone
    // is printed too.
    std::printf("frame cost, lab %d: whole frame %.2f ms = %.2fx its lit image's three passes (ambient %.2f + volumes "
                "%.2f + lit %.2f ms; done when <= 1.15x); %.2fx the additive lit pass alone\n",
                l["lab"].get<int>(), l["frame_ms"].get<double>(), l["ratio_to_view_passes"].get<double>(),
                passes["ambient"].get<double>(), passes["volumes"].get<double>(), passes["lit"].get<double>(),
                l["ratio_to_lit_pass"].get<double>());
  }
}

}  // namespace shadowlab
