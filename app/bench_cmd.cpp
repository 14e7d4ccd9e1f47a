#include "app/bench_cmd.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "app/exit_codes.h"
#include "app/command_options.h"
#include "app/imgui_offscreen.h"
#include "app/panel_lab.h"
#include "app/bench_baseline.h"
#include "app/bench_plot.h"
#include "grading/check.h"
#include "app/bench_figures.h"
#include "labs/registry.h"
#include "renderer/context.h"
#include "core/gltf_loader.h"
#include "core/image_io.h"
#include "core/platform.h"
#include "oracle/soft_truth.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// A technique is a lab's solution with some parameters set (each lab declares its own, Lab::bench): the
// benchmark composes what the labs teach.
struct Technique {
  const Lab* lab = nullptr;
  BenchTechnique entry;
  std::string family;  // colour group in the plot: the entry's, with the lab's number
};

struct BenchScene {
  std::string name;
  Scene scene;
  std::vector<std::pair<std::string, std::string>> sets;  // e.g. a grazing light
  std::optional<Bounds> view;                            // what the camera frames (default: the scene)
  std::optional<OrbitCamera> camera;                     // or a camera standing inside the scene
};

struct SizedPoint {
  float sun_deg = 0.0f;
  SoftMetrics metrics;
  double gpu_ms = 0.0;  // the point's own, unless the technique reads the light's size (timed again)
};

struct BenchPoint {
  std::string technique, family, scene;
  int map_size = 0;
  std::map<std::string, double> pass_ms;  // median per pass
  double gpu_ms = 0.0;                    // sum of the medians
  double cpu_ms = 0.0;                    // median CPU time of render()
  Metrics metrics;
  double error = 0.0;  // mean |visibility - truth| over all valid pixels
  // The same frame graded against the truth of a sun with a size (kBenchSunDegrees): a technique that
  // does not read the light's size draws the same image whatever it is.
  std::vector<SizedPoint> light_sizes;
};

// The suns with a size the benchmark grades every frame against, angular diameters in degrees: small
// (twice the real sun's 0.53) and large (a lamp a metre wide 11 m away).
constexpr float kBenchSunDegrees[] = {1.0f, 5.0f};
constexpr int kSoftStrata = 16;  // their samples per pixel: 16 x 16 (oracle/soft_truth.h states its error)
// Their truths on one scene's frame: every technique of a scene draws the same G-buffer under the same
// sun, so they are made once per scene (and again should a technique's frame or light differ).
struct SizedTruths {
  GBuffer gbuffer;
  OracleLight light;
  std::vector<SoftTruth> truths;  // one per kBenchSunDegrees
};

constexpr int kWidth = 640, kHeight = 360;
// The issue asks for an edge band of fixed width in screen pixels, so map sizes compare fairly.
constexpr int kBandPixels = 3;

// The benchmark's frame: kWidth x kHeight, the camera framing `view`.
FrameRequest bench_request(const Bounds& view) {
  FrameRequest request;
  request.camera = OrbitCamera::framing(view);
  request.width = kWidth;
  request.height = kHeight;
  return request;
}

std::vector<Technique> techniques(bool quick) {
  std::vector<Technique> out;
  for (const auto& lab : all_labs())
    for (const auto& entry : lab.bench)
      if (entry.quick || !quick) out.push_back({&lab, entry, entry.family + " (lab " + std::to_string(lab.number) + ")"});
  return out;
}

// The lab the skipping, overlay and blur figures use: the first whose solution stores moments and
// declares a blur (the most a skipped shadow update saves).
const Lab& blurred_moments_lab() {
  for (const auto& lab : all_labs())
    if (lab.hooks(Impl::Solution).technique == ShadowTechnique::Moments && lab_params(lab).find("vsm.blur_radius"))
      return lab;
  throw std::runtime_error("no lab stores blurred moments: the bench's skipping, overlay and blur figures need one");
}

std::vector<BenchScene> scenes(const std::string& scene_file) {
  std::vector<BenchScene> out;
  out.push_back({"default", make_default_scene(), {}, std::nullopt, std::nullopt});
  out.push_back({"grazing", make_default_scene(), {{"light.elevation", "10"}}, std::nullopt, std::nullopt});
  out.push_back({"stacked", make_stacked_occluders_scene(), {}, std::nullopt, std::nullopt});
  if (!scene_file.empty()) {
    out.push_back({fs::path(scene_file).stem().string(), load_gltf(scene_file), {{"light.elevation", "30"}}, std::nullopt,
                   std::nullopt});
  } else {
    // The PalmTree: 10k triangles on a 392-unit sea; the camera looks at its 80-unit island.
    const fs::path palm = data_dir() / "assets" / "models" / "PalmTree" / "PalmTree.gltf";
    Bounds island;
    island.extend(glm::vec3(-40.0f, -1.0f, -57.0f));
    island.extend(glm::vec3(38.0f, 4.0f, 22.0f));
    Scene palm_tree = load_gltf(palm);
    // The same scene seen from a camera standing on the island among the palms (lab 12's): the view
    // reaches the sea's edge, far beyond what is near the camera, where cascades are meant to win.
    const OrbitCamera on_island =
        OrbitCamera::looking({6.0f, 2.5f, 9.0f}, {-2.5f, 1.0f, 1.0f}, 45.0f, palm_tree.bounds());
    out.push_back({"palmtree", palm_tree, {{"light.elevation", "30"}}, island, std::nullopt});
    out.push_back({"palmtree-island", std::move(palm_tree), {{"light.elevation", "30"}}, std::nullopt, on_island});
  }
  return out;
}

BenchPoint measure(Renderer& renderer, const Oracle& oracle, const Technique& t, const BenchScene& s, int map_size,
                   int frames, SizedTruths& sized) {
  const Lab& lab = *t.lab;
  ParamSet params = lab_params(lab);
  // Every technique of a scene under the same light: the renderer's default direction, whatever the
  // lab's own default (lab 1's is a grazing 10 degrees), then the scene's and the technique's settings.
  for (const FloatParam* angle : {&param::light_azimuth, &param::light_elevation})
    params.set(angle->key(), angle->spec().default_value);
  for (const auto& [k, v] : s.sets) params.set_from_string(k, v);
  for (const auto& [k, v] : t.entry.sets) params.set_from_string(k, v);
  if (map_size > 0) params.set_from_string("shadow.map_size", std::to_string(map_size));
  params.set("view.debug_quad", 0.0);
  if (!renderer.set_features(lab.hooks(Impl::Solution))) throw std::runtime_error(renderer.shader_error());
  FrameRequest request = bench_request(s.view ? *s.view : s.scene.bounds());
  if (s.camera) request.camera = *s.camera;

  BenchPoint point{t.entry.name, t.family, s.name, map_size, {}, 0.0, 0.0, {}, 0.0, {}};
  // Each pass's median time over `frames` frames (after a warm-up: shader variants, allocations), each
  // forced to run the whole pipeline; returns the medians' sum.
  auto time_passes = [&](const ParamSet& with, std::map<std::string, double>& medians, double* cpu) {
    std::map<std::string, std::vector<double>> pass_ms;
    std::vector<double> cpu_ms;
    for (int frame = -1; frame < frames; ++frame) {
      renderer.invalidate_shadow_map();
      const FrameStats& stats = renderer.render(with, request);
      if (frame < 0) continue;
      for (const auto& p : stats.passes) pass_ms[std::string(p.name)].push_back(p.gpu_ms);
      cpu_ms.push_back(stats.cpu_ms);
    }
    double total = 0.0;
    for (auto& [name, v] : pass_ms) total += medians[name] = median(v);
    if (cpu) *cpu = median(cpu_ms);
    return total;
  };
  point.gpu_ms = time_passes(params, point.pass_ms, &point.cpu_ms);
  // The error, from one more frame with the G-buffer.
  request.gbuffer = true;
  renderer.render(params, request);
  BandSpec band;
  band.fixed_screen_pixels = kBandPixels;
  OracleLight light = oracle_light(renderer);
  GBuffer gbuffer = renderer.read_gbuffer();
  const std::vector<float> visibility = renderer.read_visibility();
  const Truth truth = oracle.evaluate(gbuffer, light, band);
  point.metrics = compare(truth, visibility);
  if (!light.positional) {
    if (sized.truths.empty() || sized.light.to_light != light.to_light || sized.gbuffer.covered != gbuffer.covered ||
        sized.gbuffer.position != gbuffer.position || sized.gbuffer.normal != gbuffer.normal) {
      sized.truths.clear();
      for (const float degrees : kBenchSunDegrees)
        sized.truths.push_back(evaluate_soft(oracle, gbuffer, light, glm::radians(degrees), kSoftStrata));
      sized.gbuffer = std::move(gbuffer);
      sized.light = light;
    }
    for (std::size_t k = 0; k < sized.truths.size(); ++k) {
      SizedPoint at{kBenchSunDegrees[k], compare_soft(sized.truths[k], visibility), point.gpu_ms};
      // A technique that reads the light's size (a penumbra estimate, a filter matched to the light)
      // draws another image at each size: graded on that image, and timed again.
      if (params.find("light.size")) {
        ParamSet at_size = params;
        at_size.set("light.size", kBenchSunDegrees[k]);
        renderer.render(at_size, request);
        const std::vector<float> sized_visibility = renderer.read_visibility();
        if (sized_visibility != visibility) {
          at.metrics = compare_soft(sized.truths[k], sized_visibility);
          std::map<std::string, double> unused;
          at.gpu_ms = time_passes(at_size, unused, nullptr);
        }
      }
      point.light_sizes.push_back(at);
    }
  }
  const double interior = static_cast<double>(point.metrics.interior_lit + point.metrics.interior_shadowed);
  const double edge = static_cast<double>(point.metrics.edge_pixels);
  point.error = interior + edge > 0 ? (point.metrics.mae_interior * interior + point.metrics.mae_edge * edge) / (interior + edge) : 0.0;
  return point;
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
  ImGuiOffscreen imgui(kWidth, kHeight);
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

// The lab's windowed-path frame against the bare two-pass baseline (app/bench_baseline.h), side by side
// in one run: LearnOpenGL's scene, light direction ((-2, 4, -1) toward the origin) and camera (at
// (0, 0, 3) looking down -z, 45 degrees), 1280 x 720, 1024^2 map. The lab's frame is what the window
// draws with the panel hidden and a still light: straight into a framebuffer standing for the window,
// no timing (TimingMode::Off), the shadow pass skipped; the baseline redraws its map every frame, as
// the tutorial does. Each frame is the wall time from the first call to a glFinish after the last, the
// two alternating frame by frame. Then every lab's whole frame (the same way) against its lit pass
// alone (Exact timing).
nlohmann::json measure_frame_cost(Renderer& renderer, int frames) {
  constexpr int kW = 1280, kH = 720;
  const Scene scene = make_learnopengl_scene();
  renderer.set_scene(scene);
  GlTexture color = make_texture_2d(GL_RGBA8, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, GL_LINEAR);
  GlRenderbuffer depth = GlRenderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, depth.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kW, kH);
  GlFramebuffer window = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, window.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth.id());
  check_framebuffer("the bench's window stand-in");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);

  FrameRequest request;
  request.camera = OrbitCamera::looking({0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, 2.0f}, 45.0f, scene.bounds());
  request.width = kW;
  request.height = kH;
  request.to_window = true;
  request.window_framebuffer = window.id();
  auto wall = [](const auto& draw) {
    const auto start = std::chrono::steady_clock::now();
    draw();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  auto lab_setup = [&](const Lab& lab) {
    ParamSet params = lab_params(lab);
    params.set_from_string("light.azimuth", "153.43");   // toward (-2, 4, -1)
    params.set_from_string("light.elevation", "60.79");
    params.set_from_string("shadow.map_size", "1024");
    params.set("view.debug_quad", 0.0);
    if (!renderer.set_features(lab.hooks(Impl::Solution))) throw std::runtime_error(renderer.shader_error());
    return params;
  };
  // One lab's whole frame (no timing, into the window stand-in) and each of its passes alone (Exact).
  auto frame_and_passes = [&](const ParamSet& params, std::vector<double>* frame_ms,
                              std::map<std::string, std::vector<double>>* pass_ms) {
    renderer.set_timing(TimingMode::Exact);
    for (int f = 0; f < 2; ++f) renderer.render(params, request);  // warm-up: programs, targets, the map
    for (int f = 0; f < frames; ++f) {
      renderer.set_timing(TimingMode::Off);
      frame_ms->push_back(wall([&] { renderer.render(params, request); }));
      renderer.set_timing(TimingMode::Exact);
      for (const auto& p : renderer.render(params, request).passes) (*pass_ms)[std::string(p.name)].push_back(p.gpu_ms);
    }
  };

  // PCF 3x3 (the renderer's default kernel), drawn by the lab that offers it to the bench.
  const Lab* pcf = find_lab_offering("pcf 3");
  if (!pcf) throw std::runtime_error("the frame-cost figure needs a lab offering \"pcf 3\" to the bench (PCF, 3 x 3)");
  ParamSet params = lab_setup(*pcf);
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
  nlohmann::json labs = nlohmann::json::array();
  for (const auto& lab : all_labs()) {
    const ParamSet lp = lab_setup(lab);
    std::vector<double> frame_ms;
    std::map<std::string, std::vector<double>> pass_ms;
    frame_and_passes(lp, &frame_ms, &pass_ms);
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

nlohmann::json blur_json(const std::vector<BlurTiming>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& b : rows)
    out.push_back({{"method", b.method}, {"radius", b.radius}, {"sigma", b.sigma}, {"map_size", b.map_size},
                   {"format", b.format}, {"ms_x", b.ms_x}, {"ms_y", b.ms_y}, {"ms_total", b.ms_total},
                   {"max_abs_diff_vs_separable", b.max_abs_diff_vs_separable}, {"non_finite", b.non_finite}});
  return out;
}

// Per method and radius: each direction's time, the total against the taught blur's, the moments' distance.
void print_blur_methods(const std::vector<BlurTiming>& rows) {
  for (const auto& b : rows) {
    const auto taught = std::find_if(rows.begin(), rows.end(), [&](const BlurTiming& t) {
      return t.method == "separable" && t.radius == b.radius && t.format == b.format;
    });
    std::printf("blur %s %4d r%-2d %-9s x %7.2f  y %7.2f  total %7.2f ms = %.2fx the taught blur, max |d| %.1e\n",
                b.format.c_str(), b.map_size, b.radius, b.method.c_str(), b.ms_x, b.ms_y, b.ms_total,
                taught->ms_total / b.ms_total, b.max_abs_diff_vs_separable);
  }
}

void print_technique_passes(const std::vector<TechniquePasses>& rows) {
  for (const auto& r : rows) {
    std::printf("passes, %-24s", r.name.c_str());
    for (const auto& [name, ms] : r.pass_ms) std::printf(" %s %.1f", name.c_str(), ms);
    std::printf("  | sum %.1f ms\n", r.total_ms);
  }
}

void print_oracle_cost(const OracleCost& c) {
  std::printf("oracle: %zu triangles, BVH build %.2f ms\n", c.triangles, c.build_ms);
  for (const auto& r : c.runs)
    std::printf("oracle %dx%d %-30s %8.1f ms %9llu rays %6.2f Mrays/s (%ld edge px)\n", kWidth, kHeight, r.what.c_str(),
                r.ms, static_cast<unsigned long long>(r.rays), r.mrays_per_s(), r.edge_pixels);
}

nlohmann::json technique_passes_json(const std::vector<TechniquePasses>& rows) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& r : rows) out.push_back({{"technique", r.name}, {"passes", r.pass_ms}, {"total_ms", r.total_ms}});
  return out;
}

nlohmann::json oracle_cost_json(const OracleCost& cost) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& r : cost.runs)
    runs.push_back({{"what", r.what}, {"ms", r.ms}, {"rays", r.rays}, {"mrays_per_s", r.mrays_per_s()},
                    {"edge_pixels", r.edge_pixels}});
  return {{"triangles", cost.triangles}, {"build_ms", cost.build_ms}, {"runs", runs}};
}

// The oracle's cost on the default scene's frame as the benchmark renders it (kWidth x kHeight), lit by
// the default light and by a spot-like positional light at (-4, 9, 3) with 2048 texels over 1.2 rad.
OracleCost measure_oracle(Renderer& renderer, const Scene& scene, int repeats) {
  renderer.set_features({});
  renderer.set_scene(scene);
  ParamSet params(renderer_param_specs());
  params.set("view.debug_quad", 0.0);
  FrameRequest request = bench_request(scene.bounds());
  request.gbuffer = true;
  renderer.render(params, request);
  OracleLight directional;
  directional.to_light = renderer.to_light();
  directional.image_x = renderer.light_view().image_x;
  directional.image_y = renderer.light_view().image_y;
  directional.texel_world_size = renderer.light_view().world_size.x / static_cast<float>(renderer.shadow_map_size());
  OracleLight positional;
  positional.positional = true;
  positional.position = {-4.0f, 9.0f, 3.0f};
  positional.texel_angle = 1.2f / 2048.0f;
  return measure_oracle_cost(scene, renderer.read_gbuffer(), directional, positional, repeats);
}

// The plot: one tile per scene, drawn by the code that draws it in the app's panel; `sized_lights`: the
// tiles of the suns with a size instead (two per row: one scene's sizes side by side). False when there
// is no such tile (a run recorded before light sizes): nothing written.
bool write_pareto_png(const BenchPlots& plots, const fs::path& file, bool sized_lights = false) {
  std::vector<std::string> names;
  for (const auto& [name, plot] : plots.by_scene)
    if (is_sized_light_plot(name) == sized_lights) names.push_back(name);
  if (names.empty()) return false;
  const int plot_w = 640, plot_h = 420;
  const int cols = 2, rows = static_cast<int>((names.size() + 1) / 2);
  ImGuiOffscreen imgui(cols * plot_w, rows * plot_h);
  const auto pixels = imgui.render([&] {
    int i = 0;
    for (const auto& name : names) {
      ImGui::SetNextWindowPos(ImVec2(static_cast<float>((i % cols) * plot_w), static_cast<float>((i / cols) * plot_h)));
      ImGui::SetNextWindowSize(ImVec2(static_cast<float>(plot_w), static_cast<float>(plot_h)));
      ImGui::Begin(("##plot" + name).c_str(), nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
      draw_bench_scene(plots, name, plot_w - 16.0f, plot_h - 40.0f);
      ImGui::End();
      ++i;
    }
  });
  write_png(file, cols * plot_w, rows * plot_h, pixels);
  return true;
}

std::string csv_escape(const std::string& s) { return s.find(',') == std::string::npos ? s : "\"" + s + "\""; }

// The soft truth's cost on every scene's frame (kWidth x kHeight, the scene's camera and sun): a sun of 1
// and of 5 degrees, 16 x 16 samples at every pixel (Full) against EdgeRefined sampling, side by side, with
// the hard oracle (no band) for scale, and how far EdgeRefined's truth is from Full's.
nlohmann::json measure_soft_truth(Renderer& renderer, const std::vector<BenchScene>& bench_scenes) {
  static const std::vector<ParamSpec> renderer_specs = renderer_param_specs();
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& s : bench_scenes) {
    renderer.set_features({});
    renderer.set_scene(s.scene);
    ParamSet params(renderer_specs);
    for (const auto& [k, v] : s.sets) params.set_from_string(k, v);
    params.set("view.debug_quad", 0.0);
    FrameRequest request = bench_request(s.view ? *s.view : s.scene.bounds());
    if (s.camera) request.camera = *s.camera;
    request.gbuffer = true;
    renderer.render(params, request);
    const GBuffer gbuffer = renderer.read_gbuffer();
    const Oracle oracle(s.scene);
    OracleLight sun;
    sun.to_light = renderer.to_light();
    BandSpec no_band;
    no_band.samples = 0;
    const Truth hard = oracle.evaluate(gbuffer, sun, no_band);
    for (const float degrees : kBenchSunDegrees) {
      std::fprintf(stderr, "soft truth, %s, sun %.0f deg...\n", s.name.c_str(), static_cast<double>(degrees));
      const float size = glm::radians(degrees);
      const SoftTruth full = evaluate_soft(oracle, gbuffer, sun, size, kSoftStrata, SoftSampling::Full);
      const SoftTruth edge = evaluate_soft(oracle, gbuffer, sun, size, kSoftStrata, SoftSampling::EdgeRefined);
      long valid = 0, penumbra = 0, differ = 0;
      double worst = 0.0, sum = 0.0;
      for (std::size_t i = 0; i < full.visible.size(); ++i) {
        if (!full.valid[i]) continue;
        ++valid;
        penumbra += full.visible[i] > 0.0f && full.visible[i] < 1.0f;
        const double d = std::abs(static_cast<double>(edge.visible[i]) - full.visible[i]);
        differ += d > 0.0;
        worst = std::max(worst, d);
        sum += d;
      }
      rows.push_back({{"scene", s.name}, {"sun_deg", degrees}, {"strata", kSoftStrata}, {"valid_pixels", valid},
                      {"penumbra_pixels", penumbra}, {"hard_ms", 1e3 * hard.seconds}, {"full_ms", 1e3 * full.seconds},
                      {"full_rays", full.rays}, {"edge_ms", 1e3 * edge.seconds}, {"edge_rays", edge.rays},
                      {"edge_refined_pixels", edge.refined}, {"edge_differ_pixels", differ},
                      {"edge_worst_abs_diff", worst},
                      {"edge_mean_abs_diff", valid > 0 ? sum / static_cast<double>(valid) : 0.0}});
    }
  }
  return rows;
}

void print_soft_truth(const nlohmann::json& rows) {
  for (const auto& r : rows)
    std::printf("soft truth %dx%d, %-15s sun %.0f deg: Full %7.0f ms (%5.1f M rays), EdgeRefined %6.0f ms = %.3fx "
                "(%ld of %ld px in full, %ld penumbra), hard %4.0f ms; differ %ld px, worst %.4f, mean %.1e\n",
                kWidth, kHeight, r["scene"].get<std::string>().c_str(), r["sun_deg"].get<double>(),
                r["full_ms"].get<double>(), 1e-6 * r["full_rays"].get<double>(), r["edge_ms"].get<double>(),
                r["edge_ms"].get<double>() / std::max(r["full_ms"].get<double>(), 1e-9),
                r["edge_refined_pixels"].get<long>(), r["valid_pixels"].get<long>(), r["penumbra_pixels"].get<long>(),
                r["hard_ms"].get<double>(), r["edge_differ_pixels"].get<long>(), r["edge_worst_abs_diff"].get<double>(),
                r["edge_mean_abs_diff"].get<double>());
}

}  // namespace

int run_bench(const BenchOptions& options) {
  bool usage_checked = false;  // the output folder and the scenes are the command line's: exit 2 when unusable
  try {
    make_output_dir(options.out_dir);  // created, proven writable, locked against a second run
    std::optional<BenchPlots> replot;  // --replot: a recorded run's plot drawn again, nothing measured
    if (!options.replot.empty()) replot = load_bench_plots(options.replot);
    const auto bench_scenes = replot ? decltype(scenes(options.scene_file)){} : scenes(options.scene_file);
    usage_checked = true;
    std::string error;
    auto context = HeadlessContext::create(&error);
    if (!context) throw std::runtime_error(error);

    if (replot) {
      write_pareto_png(*replot, fs::path(options.out_dir) / "pareto.png");
      const bool sized = write_pareto_png(*replot, fs::path(options.out_dir) / "pareto_light_size.png", true);
      std::printf("wrote %s/pareto.png%s from %s\n", options.out_dir.c_str(), sized ? " and pareto_light_size.png" : "",
                  options.replot.c_str());
      return 0;
    }
    if (options.frame_cost_only) {
      nlohmann::json frame_cost;
      {
        Renderer renderer;
        frame_cost = measure_frame_cost(renderer, options.quick ? 9 : 25);
      }
      write_text_atomic(fs::path(options.out_dir) / "frame_cost.json", frame_cost.dump(2) + "\n");
      print_frame_cost(frame_cost);
      return 0;
    }
    if (options.soft_truth_only) {
      nlohmann::json soft;
      {
        Renderer renderer;
        soft = measure_soft_truth(renderer, bench_scenes);
      }
      write_text_atomic(fs::path(options.out_dir) / "soft_truth.json", soft.dump(2) + "\n");
      print_soft_truth(soft);
      return 0;
    }
    const std::vector<int> sizes = options.quick ? std::vector<int>{512, 1024, 2048} : std::vector<int>{512, 1024, 2048, 4096};
    const int frames = options.quick ? 3 : 7;
    const auto techs = techniques(options.quick);
    std::size_t per_scene = 0;
    for (const auto& t : techs) per_scene += t.entry.uses_map ? sizes.size() : 1;
    const std::size_t total = bench_scenes.size() * per_scene;
    std::vector<BenchPoint> points;
    nlohmann::json skipping, overlays, frame_cost;
    std::vector<BlurTiming> blur_rows;
    std::vector<TechniquePasses> technique_rows;
    OracleCost oracle_cost;
    nlohmann::json soft_truth = nlohmann::json::array();
    const auto start = std::chrono::steady_clock::now();
    {
      Renderer renderer;
      std::size_t done = 0;
      // On a terminal one line is rewritten in place; in a log (not a terminal) a line every tenth of
      // the sweep, and no carriage returns.
      const bool terminal = platform::is_terminal(stderr);
      std::size_t next_logged = 0;
      for (const auto& s : bench_scenes) {
        renderer.set_scene(s.scene);
        const Oracle oracle(s.scene);
        SizedTruths sized;
        for (const auto& t : techs) {
          for (int size : t.entry.uses_map ? sizes : std::vector<int>{0}) {
            ++done;
            const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (terminal) {
              std::fprintf(stderr, "\r[%zu/%zu] %-10s %-9s %4d  (%.0f s)   ", done, total, s.name.c_str(), t.entry.name.c_str(),
                           size, elapsed);
            } else if (done >= next_logged || done == total) {
              std::fprintf(stderr, "[%zu/%zu] %s %s %d (%.0f s)\n", done, total, s.name.c_str(), t.entry.name.c_str(), size, elapsed);
              next_logged = done + std::max<std::size_t>(1, total / 10);
            }
            points.push_back(measure(renderer, oracle, t, s, size, frames, sized));
          }
        }
      }
      if (terminal) std::fprintf(stderr, "\n");
      std::fprintf(stderr, "frame cost against the bare two-pass baseline...\n");
      frame_cost = measure_frame_cost(renderer, options.quick ? 9 : 25);
      skipping = measure_skipping(renderer, bench_scenes.front().scene, options.quick ? 12 : 36);
      overlays = measure_overlays(renderer, bench_scenes.front().scene, options.quick ? 5 : 15);
      // The blur methods side by side at 1024^2 RG32F: the taught separable blur, the fast one, brute 2D.
      std::fprintf(stderr, "blur methods...\n");
      const Lab& vsm = blurred_moments_lab();
      ParamSet blur_params = lab_params(vsm);
      blur_params.set_from_string("shadow.map_size", "1024");
      renderer.set_features(vsm.hooks(Impl::Solution));
      renderer.set_scene(bench_scenes.front().scene);
      const FrameRequest request = bench_request(bench_scenes.front().scene.bounds());
      renderer.render(blur_params, request);
      const std::vector<int> radii = options.quick ? std::vector<int>{1, 2, 4} : std::vector<int>{1, 2, 4, 8, 16};
      blur_rows = measure_blur_methods(renderer, blur_params, radii, options.quick ? 3 : 7);
      if (!options.quick) {  // half floats too: less bandwidth, the same passes
        // The blurred-moments lab (lab 4) may not put the format on its panel: declare it here.
        if (!blur_params.find("vsm.format")) blur_params.declare(param::vsm_format.spec());
        blur_params.set_from_string("vsm.format", "RG16F");
        const auto rg16 = measure_blur_methods(renderer, blur_params, radii, 7);
        blur_rows.insert(blur_rows.end(), rg16.begin(), rg16.end());
      }
      // Every technique pass by pass at the size the labs' texts quote (1024^2 maps, 1280 x 720), and
      // the oracle's cost.
      std::fprintf(stderr, "techniques pass by pass, oracle...\n");
      constexpr int kTechniqueMapSize = 1024, kTechniqueWidth = 1280, kTechniqueHeight = 720;  // labs 6, 8, 9 quote them
      technique_rows = measure_technique_passes(renderer, kTechniqueMapSize, kTechniqueWidth, kTechniqueHeight,
                                                options.quick ? 3 : 7);
      oracle_cost = measure_oracle(renderer, bench_scenes.front().scene, options.quick ? 3 : 7);
      if (!options.quick) soft_truth = measure_soft_truth(renderer, bench_scenes);  // about 40 s here
    }

    // Each scene's points and its Pareto front (no other technique of that scene is both faster and more
    // exact), built from the JSON points by the function the app's panel uses to show a bench.json.
    nlohmann::json json_points = nlohmann::json::array();
    for (const auto& p : points) {
      nlohmann::json light_sizes = nlohmann::json::array();
      for (const auto& sized : p.light_sizes) {
        nlohmann::json entry = to_json(sized.metrics);
        entry["sun_deg"] = sized.sun_deg;
        entry["error"] = sized.metrics.mae;
        entry["gpu_ms"] = sized.gpu_ms;
        light_sizes.push_back(entry);
      }
      json_points.push_back({{"scene", p.scene}, {"technique", p.technique}, {"family", p.family},
                             {"map_size", p.map_size}, {"gpu_ms", p.gpu_ms}, {"cpu_ms", p.cpu_ms}, {"error", p.error},
                             {"passes", p.pass_ms}, {"metrics", to_json(p.metrics)}, {"light_sizes", light_sizes}});
    }
    const BenchPlots plots = bench_plots_from_json({{"points", json_points}});

    const fs::path out(options.out_dir);
    std::ostringstream csv;
    csv << "scene,technique,map_size,gpu_ms,cpu_ms,error,acne_all,leak_all,bleeding,mae_interior,mae_edge,pareto,passes\n";
    std::map<std::string, std::size_t> index_in_scene;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const BenchPoint& p = points[i];
      const bool pareto = plots.by_scene.at(p.scene)[index_in_scene[p.scene]++].pareto;
      json_points[i]["pareto"] = pareto;
      for (auto& entry : json_points[i]["light_sizes"]) {
        const std::string plot = sized_light_plot(p.scene, entry["sun_deg"].get<double>());
        entry["pareto"] = plots.by_scene.at(plot)[index_in_scene[plot]++].pareto;
      }
      std::string passes;
      for (const auto& [name, ms] : p.pass_ms) passes += (passes.empty() ? "" : " ") + name + "=" + std::to_string(ms);
      csv << p.scene << ',' << csv_escape(p.technique) << ',' << p.map_size << ',' << p.gpu_ms << ',' << p.cpu_ms << ','
          << p.error << ',' << p.metrics.acne_rate_all << ',' << p.metrics.leak_rate_all << ',' << p.metrics.bleeding_rate
          << ',' << p.metrics.mae_interior << ',' << p.metrics.mae_edge << ',' << (pareto ? 1 : 0) << ',' << passes << '\n';
    }
    write_text_atomic(out / "bench.csv", csv.str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json report = {{"quick", options.quick},
                             {"frames_per_point", frames},
                             {"resolution", {kWidth, kHeight}},
                             {"edge_band_screen_pixels", kBandPixels},
                             {"error", "mean |visibility - truth| over all valid (light-facing) pixels"},
                             {"seconds", seconds},
                             {"points", json_points},
                             {"skipping", skipping},
                             {"frame_cost", frame_cost},
                             {"hidden_views", overlays},
                             {"blur_methods", blur_json(blur_rows)},
                             {"technique_passes", technique_passes_json(technique_rows)},
                             {"oracle_cost", oracle_cost_json(oracle_cost)},
                             {"soft_truth_cost", soft_truth}};
    write_text_atomic(out / "bench.json", report.dump(2) + "\n");

    write_pareto_png(plots, out / "pareto.png");
    write_pareto_png(plots, out / "pareto_light_size.png", true);
    std::printf("%zu points in %.0f s; wrote %s/bench.csv, bench.json, pareto.png\n", points.size(), seconds,
                options.out_dir.c_str());
    print_frame_cost(frame_cost);
    std::printf("steady frame with skipping: %.2f ms = %.2f x the lit pass alone (%.2f ms); without skipping %.2f ms\n",
                skipping["with_skipping_ms"].get<double>(), skipping["ratio_to_lit_pass"].get<double>(),
                skipping["lit_pass_ms"].get<double>(), skipping["without_skipping_ms"].get<double>());
    std::printf("views: debug quads %.2f ms, light volume %.2f ms (lit pass %.2f ms); hidden: %ld and %ld passes in %d "
                "frames; panel %.2f ms per offscreen build+draw vs %.2f ms with it hidden\n",
                overlays["debug_quad_ms"].get<double>(), overlays["light_volume_ms"].get<double>(),
                overlays["lit_pass_ms"].get<double>(), overlays["debug_quad_passes_hidden"].get<long>(),
                overlays["light_volume_passes_hidden"].get<long>(), overlays["frames"].get<int>(),
                overlays["panel_ui_ms"].get<double>(), overlays["no_panel_ui_ms"].get<double>());
    print_blur_methods(blur_rows);
    print_technique_passes(technique_rows);
    print_oracle_cost(oracle_cost);
    print_soft_truth(soft_truth);
    for (const auto& [name, plot] : plots.by_scene) {
      std::printf("front, %s:", name.c_str());
      std::vector<PlotPoint> front;
      for (const auto& p : plot)
        if (p.pareto) front.push_back(p);
      std::sort(front.begin(), front.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.time_ms < b.time_ms; });
      for (const auto& p : front) std::printf("  %s (%.1f ms, %.4f)", p.label.c_str(), p.time_ms, p.error);
      std::printf("\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%sshadowlab bench: %s\n", platform::is_terminal(stderr) ? "\n" : "", e.what());
    return usage_checked ? kExitRuntime : kExitUsage;
  }
}

}  // namespace shadowlab
