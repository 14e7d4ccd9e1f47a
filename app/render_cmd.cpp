#include "app/render_cmd.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "app/command_options.h"
#include "app/exit_codes.h"
#include "app/imgui_offscreen.h"
#include "app/panel_lab.h"
#include "app/split_view.h"
#include "app/view_annotations.h"
#include "grading/check.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "renderer/context.h"
#include "core/gltf_loader.h"
#include "core/image_io.h"
#include "core/platform.h"
#include "core/untrusted.h"
#include "renderer/renderer.h"
#include "renderer/shader.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

nlohmann::json matrix_json(const glm::mat4& m) {
  // Column-major, as GL and GLM store it: 16 numbers.
  const float* p = glm::value_ptr(m);
  return std::vector<float>(p, p + 16);
}

// The lab --lab names, or why there is none.
const Lab& render_lab(int number) {
  const Lab* lab = find_lab(number);
  if (!lab) {
    std::string valid;
    for (const auto& l : all_labs()) valid += (valid.empty() ? "" : ", ") + std::to_string(l.number);
    throw std::runtime_error("--lab " + std::to_string(number) + ": no such lab; valid: " + valid);
  }
  return *lab;
}

// What the panel shows beside the frame (--panel).
struct PanelInputs {
  const Lab* lab = nullptr;
  Impl impl = Impl::Solution;
  ParamSet* params = nullptr;
  const Scene* scene = nullptr;
  const FrameStats* stats = nullptr;
  const CheckResult* check = nullptr;
  const std::optional<BenchPlots>* bench_plots = nullptr;
  PenumbraPanelState* penumbra = nullptr;
  const OrbitCamera* camera = nullptr;
};

// The window's panel, drawn by the same function over the same frame.
std::vector<std::uint8_t> draw_panel_over(const RenderOptions& options, const PanelInputs& in, const Renderer& renderer,
                                          const std::vector<std::uint8_t>& frame) {
  const Lab* lab = in.lab;
  ParamSet& params = *in.params;
  const Scene& scene = *in.scene;
  const FrameStats& stats = *in.stats;
  const std::optional<BenchPlots>& bench_plots = *in.bench_plots;
  PenumbraPanelState& penumbra = *in.penumbra;
  std::vector<std::uint8_t> color = frame;
  const LabText text = load_lab_text(*lab);
  ImGuiOffscreen offscreen(options.width, options.height);
  const UiScale scale = plan_ui_scale(options.ui_scale, 1.0f, 1.0f);
  const UiFonts fonts = offscreen.use_fonts(data_dir() / "assets" / "fonts", scale);
  PanelModel model;
  model.fonts = &fonts;
  model.ui_scale = scale.style;
  model.gl_summary = gl_summary();
  model.gl_fallbacks = gl_fallbacks();
  model.lab = lab;
  model.impl = in.impl;
  model.params = &params;
  model.stats = &stats;
  model.triangles = scene.triangle_count();
  model.scene_name = scene.name;
  model.lab_text = &text;
  model.check = in.check;
  model.interactive = false;
  BenchPanelState bench;
  bench.open = bench_plots.has_value();
  bench.path = options.bench_file;
  if (bench_plots) {
    model.bench = &bench;
    model.bench_plots = &*bench_plots;
  }
  if (penumbra.open) {
    model.penumbra = &penumbra;
    model.penumbra_key = penumbra_view_key(params, *in.camera);
  }
  color = offscreen.render(
      [&] {
        draw_view_annotations(renderer.annotations(), options.width, options.height, 0.0f,
                              static_cast<float>(options.width));
        draw_lab_panel(model);
        draw_pass_overlay(stats, nullptr);
      },
      &color);
  return color;
}

// --buffers: the G-buffer's positions and normals and the visibility, as .npy files.
void write_buffers(Renderer& renderer, const fs::path& out) {
  const GBuffer g = renderer.read_gbuffer();
  std::vector<float> flat(g.position.size() * 3);
  for (std::size_t i = 0; i < g.position.size(); ++i)
    for (int c = 0; c < 3; ++c) flat[3 * i + static_cast<std::size_t>(c)] = g.position[i][c];
  write_npy(out / "position.npy", g.width, g.height, 3, flat);
  for (std::size_t i = 0; i < g.normal.size(); ++i)
    for (int c = 0; c < 3; ++c) flat[3 * i + static_cast<std::size_t>(c)] = g.normal[i][c];
  write_npy(out / "normal.npy", g.width, g.height, 3, flat);
  write_npy(out / "visibility.npy", g.width, g.height, 1, renderer.read_visibility());
}

// render.json: what was drawn, with which parameters, matrices and GL.
nlohmann::json render_json(const RenderOptions& options, const Lab& lab, const Scene& scene, const ParamSet& params,
                           const Renderer& renderer, const FrameStats& stats, const std::string& context_platform) {
  const GlInfo gl = query_gl_info();
  nlohmann::json j = {
      {"lab", lab.number},
      {"slug", lab.slug},
      {"impl", options.impl},
      {"scene", scene.name},
      {"triangles", scene.triangle_count()},
      {"width", options.width},
      {"height", options.height},
      {"parameters", params.to_json()},
      {"camera", {{"view", matrix_json(renderer.camera_view())}, {"projection", matrix_json(renderer.camera_projection())}}},
      {"light",
       {{"to_light", {renderer.to_light().x, renderer.to_light().y, renderer.to_light().z}},
        {"view", matrix_json(renderer.light_view().view)},
        {"projection", matrix_json(renderer.light_view().projection)}}},
      {"stats", stats.to_json()},
      {"gl",
       {{"renderer", gl.renderer},
        {"version", gl.version},
        {"major", gl.major},
        {"minor", gl.minor},
        {"context", context_platform},
        {"fallbacks", gl_fallbacks()}}},
      {"matrix_layout", "column-major"},
      // The camera and light matrices take positions relative to this world point (scene.local_origin;
      // the world's origin when it is off); position.npy is in the scene's own frame.
      {"local_origin", {renderer.placement().origin().x, renderer.placement().origin().y, renderer.placement().origin().z}},
  };
  return j;
}

// --shadow-test NAME: the registered test (null without the option), its parameters declared in `params`
// (what the lab declares keeps the lab's default). An unknown name is a usage error.
const ShadowTest* shadow_test_option(const std::string& name, ParamSet& params) {
  if (name.empty()) return nullptr;
  const ShadowTest* test = nullptr;
  try {
    test = &find_shadow_test(name);
  } catch (const std::exception& e) {
    throw std::invalid_argument(std::string("--shadow-test: ") + e.what());
  }
  for (const ParamSpec& spec : test->params)
    if (!params.find(spec.key)) params.declare(spec);
  return test;
}

}  // namespace

int run_render(const RenderOptions& options) {
  // Everything the command line names is checked first (exit 2 when it cannot be used); what fails
  // after that is the tool's own failure (exit 3).
  bool usage_checked = false;
  try {
    const Lab* lab = &render_lab(options.lab);
    ParamSet params = lab_params(*lab);
    const ShadowTest* shadow_test = shadow_test_option(options.shadow_test, params);
    const Preset* preset = apply_preset_option(params, *lab, options.preset);
    for (const auto& a : options.assignments) apply_set_option(params, a);
    const Scene scene = scene_option(options.scene_file, preset);
    const OrbitCamera camera = view_camera(options.camera, preset, scene, params);
    std::optional<BenchPlots> bench_plots;
    if (!options.bench_file.empty()) bench_plots = load_bench_plots(options.bench_file);
    make_output_dir(options.out_dir);
    usage_checked = true;

    std::string error;
    auto context = HeadlessContext::create(&error);
    if (!context) throw std::runtime_error(error);
    // The renderer lives in this scope so its GL objects go before the context does.
    {
      const Impl impl = options.impl == "exercise" ? Impl::Exercise : Impl::Solution;
      std::optional<CheckResult> check;
      if (options.panel && options.panel_check && lab->check) check = run_lab_check(*lab, impl, scene, !options.scene_file.empty());
      Renderer renderer;
      Features features = lab->hooks(impl);
      if (shadow_test) {  // the test's own file in the visibility slot, with its uniforms
        features.shadow_test = shadow_test->name;
        features.includes.erase("lab/visibility.glsl");
      }
      if (!renderer.set_features(features)) throw std::runtime_error(renderer.shader_error());
      renderer.set_scene(scene);
      PenumbraPanelState penumbra;
      std::unique_ptr<Oracle> oracle;
      if (options.panel && options.penumbra) {
        oracle = std::make_unique<Oracle>(renderer.scene());
        penumbra.open = true;
        penumbra.last = measure_penumbra(renderer, params, camera, *oracle, std::min(options.width, 640),
                                         std::max(1, options.height * std::min(options.width, 640) / options.width));
      }
      FrameRequest request;
      request.camera = camera;
      request.width = options.width;
      request.height = options.height;
      request.gbuffer = options.buffers;
      const FrameStats& stats = renderer.render(params, request);

      const fs::path out(options.out_dir);
      std::vector<std::uint8_t> color = renderer.read_color();
      if (options.panel) {
        const PanelInputs in{lab, impl, &params, &scene, &stats, check ? &*check : nullptr, &bench_plots, &penumbra,
                             &camera};
        color = draw_panel_over(options, in, renderer, color);
      }
      write_png(out / "final.png", options.width, options.height, color);
      int map_size = 0;
      const auto map_image = renderer.shadow_map_image(&map_size);
      write_png(out / "shadow_map.png", map_size, map_size, map_image);
      if (options.buffers) write_buffers(renderer, out);
      const nlohmann::json j = render_json(options, *lab, scene, params, renderer, stats, context->platform());
      write_text_atomic(out / "render.json", j.dump(2) + "\n");
      std::printf("wrote %s/final.png, shadow_map.png, render.json%s (%zu triangles, %.1f ms CPU)\n",
                  options.out_dir.c_str(), options.buffers ? ", position.npy, normal.npy, visibility.npy" : "",
                  scene.triangle_count(), stats.cpu_ms);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab render: %s\n", one_line_error(e.what()).c_str());
    return usage_checked ? kExitRuntime : kExitUsage;
  }
}

}  // namespace shadowlab
