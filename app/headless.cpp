#include "app/headless.h"

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

namespace shadowlab {

namespace fs = std::filesystem;

Scene load_scene_or_default(const std::string& path) {
  if (path.empty()) return make_default_scene();
  std::vector<std::string> warnings;
  Scene scene = load_gltf(path, {}, &warnings);
  for (const std::string& w : warnings)
    std::fprintf(stderr, "shadowlab: warning: %s: %s\n", printable(path, 400).c_str(), printable(w, 400).c_str());
  return scene;
}

std::string one_line_error(const std::string& message) {
  std::string m = message;
  while (!m.empty() && m.back() == '\n') m.pop_back();
  const auto nl = m.find('\n');
  if (nl == std::string::npos || m.find('\n', nl + 1) != std::string::npos) return m;
  return m.substr(0, nl) + " " + m.substr(nl + 1);
}

void prove_writable_folder(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw std::runtime_error(dir + ": cannot create the output folder" + (ec ? ": " + ec.message() : std::string()));
  try {
    platform::probe_writable(dir);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(dir + ": the output folder is not writable: " + e.what());
  }
}

void make_output_dir(const std::string& dir) {
  prove_writable_folder(dir);
  std::string holder;
  bool locked = false;
  try {
    locked = platform::lock_folder(dir, &holder);
  } catch (const platform::FileError& e) {
    throw std::runtime_error(dir + ": cannot lock the output folder: " + e.what());
  }
  if (!locked)
    throw std::runtime_error(dir + ": the output folder is in use by another shadowlab run" +
                             (holder.empty() ? std::string() : " (process " + holder + ")") +
                             "; wait for it to finish or choose another --out");
}

void apply_set_option(ParamSet& params, const std::string& assignment) {
  try {
    params.apply_assignment(assignment);
  } catch (const std::exception& e) {
    throw std::invalid_argument("--set " + assignment + ": " + e.what());
  }
}

void apply_preset_option(ParamSet& params, const Lab& lab, const std::string& name) {
  if (name.empty()) return;
  try {
    apply_preset(params, find_preset(lab, name));
  } catch (const std::exception& e) {
    throw std::invalid_argument("--preset " + name + ": " + e.what());
  }
}

OrbitCamera camera_option(const std::string& spec, const Bounds& bounds) {
  const OrbitCamera framed = OrbitCamera::framing(bounds);
  if (spec.empty()) return framed;
  glm::vec3 eye = framed.eye(), target = framed.target;
  float fov = framed.fov_y_deg;
  std::istringstream words(spec);
  std::string word;
  auto bad = [&](const std::string& why) { return std::invalid_argument("--camera " + spec + ": " + word + ": " + why); };
  auto number = [&](const std::string& text) {
    std::size_t used = 0;
    float v = 0.0f;
    try {
      v = std::stof(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || !std::isfinite(v)) throw bad("'" + text + "' is not a number");
    return v;
  };
  while (words >> word) {
    const auto eq = word.find('=');
    const std::string key = word.substr(0, eq), value = eq == std::string::npos ? "" : word.substr(eq + 1);
    if (key == "eye" || key == "target") {
      glm::vec3 v{0.0f};
      std::istringstream parts(value);
      std::string part;
      int n = 0;
      while (std::getline(parts, part, ',')) {
        if (n == 3) throw bad("three numbers expected, x,y,z");
        v[n++] = number(part);
      }
      if (n != 3) throw bad("three numbers expected, x,y,z");
      (key == "eye" ? eye : target) = v;
    } else if (key == "fov") {
      fov = number(value);
      if (fov < 1.0f || fov > 170.0f) throw bad("the field of view is 1-170 degrees");
    } else {
      throw bad("expected eye=x,y,z, target=x,y,z or fov=deg");
    }
  }
  word = "eye, target";
  if (glm::length(eye - target) < 1e-6f) throw bad("the eye and the target are the same point");
  return OrbitCamera::looking(eye, target, fov, bounds);
}

void parse_size_option(const std::string& spec, int* width, int* height) {
  const auto x = spec.find('x');
  std::size_t used_w = 0, used_h = 0;
  int w = 0, h = 0;
  try {
    if (x != std::string::npos) {
      w = std::stoi(spec.substr(0, x), &used_w);
      h = std::stoi(spec.substr(x + 1), &used_h);
    }
  } catch (const std::exception&) {
    w = h = 0;
  }
  if (x == std::string::npos || used_w != x || used_h != spec.size() - x - 1 || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw std::invalid_argument("--size " + spec + ": expected WxH, each 16-8192 pixels (e.g. 1280x720)");
  *width = w;
  *height = h;
}

namespace {

nlohmann::json matrix_json(const glm::mat4& m) {
  // Column-major, as GL and GLM store it: 16 numbers.
  const float* p = glm::value_ptr(m);
  return std::vector<float>(p, p + 16);
}

}  // namespace

int run_render(const RenderOptions& options) {
  // Everything the command line names is checked first (exit 2 when it cannot be used); what fails
  // after that is the tool's own failure (exit 3).
  bool usage_checked = false;
  try {
    const Lab* lab = find_lab(options.lab);
    if (!lab) {
      std::string valid;
      for (const auto& l : all_labs()) valid += (valid.empty() ? "" : ", ") + std::to_string(l.number);
      throw std::runtime_error("--lab " + std::to_string(options.lab) + ": no such lab; valid: " + valid);
    }
    ParamSet params = lab_params(*lab);
    apply_preset_option(params, *lab, options.preset);
    for (const auto& a : options.assignments) apply_set_option(params, a);
    const Scene scene = load_scene_or_default(options.scene_file);
    const OrbitCamera camera = options.camera.empty() ? frame_scene_camera(scene, params)
                                                      : camera_option(options.camera, frame_scene_bounds(scene, params));
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
      if (options.panel && options.panel_check && lab->check) check = run_lab_check(*lab, impl, scene);
      Renderer renderer;
      if (!renderer.set_features(lab->hooks(impl))) throw std::runtime_error(renderer.shader_error());
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
        // The window's panel, drawn by the same function over the same frame.
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
        model.impl = impl;
        model.params = &params;
        model.stats = &stats;
        model.triangles = scene.triangle_count();
        model.scene_name = scene.name;
        model.lab_text = &text;
        model.check = check ? &*check : nullptr;
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
          model.penumbra_key = penumbra_view_key(params, camera);
        }
        color = offscreen.render(
            [&] {
              draw_view_annotations(renderer.annotations(), options.width, options.height, 0.0f,
                                    static_cast<float>(options.width));
              draw_lab_panel(model);
              draw_pass_overlay(stats, nullptr);
            },
            &color);
      }
      write_png(out / "final.png", options.width, options.height, color);
      int map_size = 0;
      const auto map_image = renderer.shadow_map_image(&map_size);
      write_png(out / "shadow_map.png", map_size, map_size, map_image);
      if (options.buffers) {
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
      const GlInfo gl = query_gl_info();
      nlohmann::json j = {
          {"lab", lab->number},
          {"slug", lab->slug},
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
            {"context", context->platform()},
            {"fallbacks", gl_fallbacks()}}},
          {"matrix_layout", "column-major"},
          // The camera and light matrices take positions relative to this world point (scene.local_origin;
          // the world's origin when it is off); position.npy is in the scene's own frame.
          {"local_origin", {renderer.placement().origin().x, renderer.placement().origin().y, renderer.placement().origin().z}},
      };
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

namespace {

// A lab's presets as `labs --presets --json` lists them: what each sets, the artifact it provokes and the
// preset that fixes it (null where there is none), in the lab's order.
nlohmann::json presets_json(const Lab& lab) {
  nlohmann::json presets = nlohmann::json::array();
  const auto or_null = [](const std::string& s) { return s.empty() ? nlohmann::json(nullptr) : nlohmann::json(s); };
  for (const auto& p : lab.presets)
    presets.push_back({{"name", p.name}, {"description", p.description}, {"values", p.values},
                       {"provokes", or_null(p.artifact.provokes)}, {"fixed_by", or_null(p.artifact.fixed_by)}});
  return presets;
}

}  // namespace

int run_list_labs(bool show_params, bool json, bool show_presets) {
  if (json) {  // for scripts (graders, the corpus test, lecture pictures): what each lab consists of
    nlohmann::json labs = nlohmann::json::array();
    for (const auto& lab : all_labs()) {
      labs.push_back({{"number", lab.number}, {"slug", lab.slug}, {"folder", lab.folder()}, {"title", lab.title},
                      {"exercise_files", lab.exercise_files}, {"solution_files", lab.solution_files},
                      {"offered_includes", lab.offered_includes}, {"has_check", static_cast<bool>(lab.check)}});
      if (show_presets) labs.back()["presets"] = presets_json(lab);
    }
    std::printf("%s\n", nlohmann::json{{"labs", labs}}.dump(2).c_str());
    return 0;
  }
  for (const auto& lab : all_labs()) {
    std::printf("%2d  %-22s %s\n", lab.number, lab.title.c_str(), lab.summary.c_str());
    if (show_presets) {
      for (const auto& p : lab.presets) {
        std::string artifact;
        if (!p.artifact.provokes.empty()) artifact = "  [" + p.artifact.provokes + "]";
        if (!p.artifact.fixed_by.empty()) artifact += " fixed by '" + p.artifact.fixed_by + "'";
        std::printf("      --preset '%s'%s  %s\n", p.name.c_str(), artifact.c_str(), p.description.c_str());
      }
    }
    if (!show_params) continue;
    const ParamSet params = lab_params(lab);
    for (const auto& s : params.specs()) {
      std::string range;
      if (s.kind == ParamKind::Choice) {
        for (const auto& c : s.choices) range += (range.empty() ? "" : "|") + c;
      } else if (s.kind == ParamKind::Bool) {
        range = "true|false";
      } else {
        range = std::to_string(s.min) + ".." + std::to_string(s.max);
      }
      std::printf("      --set %s=%s  [%s]  %s\n", s.key.c_str(), params.format(s.key).c_str(), range.c_str(), s.label.c_str());
    }
  }
  return 0;
}

}  // namespace shadowlab
