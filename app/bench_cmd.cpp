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
#include "app/bench_frame_cost.h"
#include "app/bench_ao.h"
#include "app/bench_plot.h"
#include "app/bench_pareto_png.h"
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

// The issue asks for an edge band of fixed width in screen pixels, so map sizes compare fairly.
constexpr int kBandPixels = 3;

std::vector<Technique> techniques(bool quick) {
  std::vector<Technique> out;
  for (const auto& lab : all_labs())
    for (const auto& entry : lab.bench)
      if (entry.quick || !quick) out.push_back({&lab, entry, entry.family + " (lab " + std::to_string(lab.number) + ")"});
  return out;
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
    std::printf("oracle %dx%d %-30s %8.1f ms %9llu rays %6.2f Mrays/s (%ld edge px)\n", kBenchWidth, kBenchHeight, r.what.c_str(),
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

// The oracle's cost on the default scene's frame as the benchmark renders it (kBenchWidth x kBenchHeight), lit by
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

std::string csv_escape(const std::string& s) { return s.find(',') == std::string::npos ? s : "\"" + s + "\""; }

// The soft truth's cost on every scene's frame (kBenchWidth x kBenchHeight, the scene's camera and sun): a sun of 1
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
                kBenchWidth, kBenchHeight, r["scene"].get<std::string>().c_str(), r["sun_deg"].get<double>(),
                r["full_ms"].get<double>(), 1e-6 * r["full_rays"].get<double>(), r["edge_ms"].get<double>(),
                r["edge_ms"].get<double>() / std::max(r["full_ms"].get<double>(), 1e-9),
                r["edge_refined_pixels"].get<long>(), r["valid_pixels"].get<long>(), r["penumbra_pixels"].get<long>(),
                r["hard_ms"].get<double>(), r["edge_differ_pixels"].get<long>(), r["edge_worst_abs_diff"].get<double>(),
                r["edge_mean_abs_diff"].get<double>());
}

// --replot: a recorded run's plot drawn again, nothing measured.
int replot_bench(const BenchOptions& options, const BenchPlots& replot) {
  write_pareto_png(replot, fs::path(options.out_dir) / "pareto.png");
  const bool sized = write_pareto_png(replot, fs::path(options.out_dir) / "pareto_light_size.png", true);
  std::printf("wrote %s/pareto.png%s from %s\n", options.out_dir.c_str(), sized ? " and pareto_light_size.png" : "",
              options.replot.c_str());
  return 0;
}

// --frame-cost: the frame-cost figure alone.
int bench_frame_cost_only(const BenchOptions& options) {
  nlohmann::json frame_cost;
  {
    Renderer renderer;
    frame_cost = measure_frame_cost(renderer, options.quick ? 9 : 25);
  }
  write_text_atomic(fs::path(options.out_dir) / "frame_cost.json", frame_cost.dump(2) + "\n");
  print_frame_cost(frame_cost);
  return 0;
}

// --ao: the AO front alone.
int bench_ao_only(const BenchOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json ao;
  {
    Renderer renderer;
    ao = measure_ao_front(renderer, options.quick);
  }
  ao["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_text_atomic(fs::path(options.out_dir) / "ao_front.json", ao.dump(2) + "\n");
  write_pareto_png(bench_plots_from_json(ao), fs::path(options.out_dir) / "ao_pareto.png");
  std::printf("%zu AO points in %.0f s; wrote %s/ao_front.json, ao_pareto.png\n", ao.at("points").size(),
              ao.at("seconds").get<double>(), options.out_dir.c_str());
  print_ao_front(ao);
  return 0;
}

// --soft-truth: the soft truth's cost alone.
int bench_soft_truth_only(const BenchOptions& options, const std::vector<BenchScene>& bench_scenes) {
  nlohmann::json soft;
  {
    Renderer renderer;
    soft = measure_soft_truth(renderer, bench_scenes);
  }
  write_text_atomic(fs::path(options.out_dir) / "soft_truth.json", soft.dump(2) + "\n");
  print_soft_truth(soft);
  return 0;
}

// The sweep: every technique at every map size (one point when it uses no map) on every scene.
std::vector<BenchPoint> sweep(Renderer& renderer, const std::vector<BenchScene>& bench_scenes,
                              const std::vector<Technique>& techs, const std::vector<int>& sizes, int frames,
                              std::chrono::steady_clock::time_point start) {
  std::size_t per_scene = 0;
  for (const auto& t : techs) per_scene += t.entry.uses_map ? sizes.size() : 1;
  const std::size_t total = bench_scenes.size() * per_scene;
  std::vector<BenchPoint> points;
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
  return points;
}

// What the bench measures beside its sweep.
struct BenchFigures {
  nlohmann::json skipping, overlays, frame_cost;
  std::vector<BlurTiming> blur_rows;
  std::vector<TechniquePasses> technique_rows;
  OracleCost oracle_cost;
  nlohmann::json soft_truth = nlohmann::json::array();
};

BenchFigures measure_figures(Renderer& renderer, const BenchOptions& options, const std::vector<BenchScene>& bench_scenes) {
  BenchFigures f;
  std::fprintf(stderr, "frame cost against the bare two-pass baseline...\n");
  f.frame_cost = measure_frame_cost(renderer, options.quick ? 9 : 25);
  f.skipping = measure_skipping(renderer, bench_scenes.front().scene, options.quick ? 12 : 36);
  f.overlays = measure_overlays(renderer, bench_scenes.front().scene, options.quick ? 5 : 15);
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
  f.blur_rows = measure_blur_methods(renderer, blur_params, radii, options.quick ? 3 : 7);
  if (!options.quick) {  // half floats too: less bandwidth, the same passes
    // The blurred-moments lab (lab 4) may not put the format on its panel: declare it here.
    if (!blur_params.find("vsm.format")) blur_params.declare(param::vsm_format.spec());
    blur_params.set_from_string("vsm.format", "RG16F");
    const auto rg16 = measure_blur_methods(renderer, blur_params, radii, 7);
    f.blur_rows.insert(f.blur_rows.end(), rg16.begin(), rg16.end());
  }
  // Every technique pass by pass at the size the labs' texts quote (1024^2 maps, 1280 x 720), and
  // the oracle's cost.
  std::fprintf(stderr, "techniques pass by pass, oracle...\n");
  constexpr int kTechniqueMapSize = 1024, kTechniqueWidth = 1280, kTechniqueHeight = 720;  // labs 6, 8, 9 quote them
  f.technique_rows = measure_technique_passes(renderer, kTechniqueMapSize, kTechniqueWidth, kTechniqueHeight,
                                              options.quick ? 3 : 7);
  f.oracle_cost = measure_oracle(renderer, bench_scenes.front().scene, options.quick ? 3 : 7);
  if (!options.quick) f.soft_truth = measure_soft_truth(renderer, bench_scenes);  // about 40 s here
  return f;
}

// The points as bench.json holds them (their Pareto flags are set by bench_csv).
nlohmann::json points_json(const std::vector<BenchPoint>& points) {
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
  return json_points;
}

// bench.csv's text; marks each point of `json_points` (and each of its light sizes) on its Pareto front or not.
std::string bench_csv(const std::vector<BenchPoint>& points, const BenchPlots& plots, nlohmann::json& json_points) {
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
  return csv.str();
}

void print_bench(const BenchFigures& f, const BenchPlots& plots) {
  print_frame_cost(f.frame_cost);
  print_skipping(f.skipping);
  print_overlays(f.overlays);
  print_blur_methods(f.blur_rows);
  print_technique_passes(f.technique_rows);
  print_oracle_cost(f.oracle_cost);
  print_soft_truth(f.soft_truth);
  for (const auto& [name, plot] : plots.by_scene) {
    std::printf("front, %s:", name.c_str());
    std::vector<PlotPoint> front;
    for (const auto& p : plot)
      if (p.pareto) front.push_back(p);
    std::sort(front.begin(), front.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.time_ms < b.time_ms; });
    for (const auto& p : front) std::printf("  %s (%.1f ms, %.4f)", p.label.c_str(), p.time_ms, p.error);
    std::printf("\n");
  }
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

    if (replot) return replot_bench(options, *replot);
    if (options.frame_cost_only) return bench_frame_cost_only(options);
    if (options.soft_truth_only) return bench_soft_truth_only(options, bench_scenes);
    if (options.ao_only) return bench_ao_only(options);
    const std::vector<int> sizes = options.quick ? std::vector<int>{512, 1024, 2048} : std::vector<int>{512, 1024, 2048, 4096};
    const int frames = options.quick ? 3 : 7;
    const auto techs = techniques(options.quick);
    std::vector<BenchPoint> points;
    BenchFigures figures;
    nlohmann::json ao;
    const auto start = std::chrono::steady_clock::now();
    {
      Renderer renderer;
      points = sweep(renderer, bench_scenes, techs, sizes, frames, start);
      figures = measure_figures(renderer, options, bench_scenes);
      const auto ao_start = std::chrono::steady_clock::now();
      ao = measure_ao_front(renderer, options.quick);
      ao["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - ao_start).count();
    }

    // Each scene's points and its Pareto front (no other technique of that scene is both faster and more
    // exact), built from the JSON points by the function the app's panel uses to show a bench.json.
    nlohmann::json json_points = points_json(points);
    const BenchPlots plots = bench_plots_from_json({{"points", json_points}});

    const fs::path out(options.out_dir);
    write_text_atomic(out / "bench.csv", bench_csv(points, plots, json_points));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    nlohmann::json report = {{"quick", options.quick},
                             {"frames_per_point", frames},
                             {"resolution", {kBenchWidth, kBenchHeight}},
                             {"edge_band_screen_pixels", kBandPixels},
                             {"error", "mean |visibility - truth| over all valid (light-facing) pixels"},
                             {"seconds", seconds},
                             {"points", json_points},
                             {"skipping", figures.skipping},
                             {"frame_cost", figures.frame_cost},
                             {"hidden_views", figures.overlays},
                             {"blur_methods", blur_json(figures.blur_rows)},
                             {"technique_passes", technique_passes_json(figures.technique_rows)},
                             {"oracle_cost", oracle_cost_json(figures.oracle_cost)},
                             {"soft_truth_cost", figures.soft_truth},
                             {"ao", ao}};
    write_text_atomic(out / "bench.json", report.dump(2) + "\n");

    write_pareto_png(plots, out / "pareto.png");
    write_pareto_png(plots, out / "pareto_light_size.png", true);
    write_pareto_png(bench_plots_from_json(ao), out / "ao_pareto.png");
    std::printf("%zu points in %.0f s; wrote %s/bench.csv, bench.json, pareto.png, ao_pareto.png\n", points.size(),
                seconds, options.out_dir.c_str());
    print_bench(figures, plots);
    print_ao_front(ao);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%sshadowlab bench: %s\n", platform::is_terminal(stderr) ? "\n" : "", e.what());
    return usage_checked ? kExitRuntime : kExitUsage;
  }
}

}  // namespace shadowlab
