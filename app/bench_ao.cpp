#include "app/bench_ao.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "app/bench_figures.h"
#include "app/bench_frame_cost.h"
#include "app/bench_plot.h"
#include "core/ao_params.h"
#include "core/scene.h"
#include "grading/lab.h"
#include "labs/registry.h"
#include "oracle/ao_metrics.h"
#include "renderer/renderer.h"

namespace shadowlab {

namespace {

constexpr float kAoRadius = 0.5f;  // lab 17's radius
constexpr const char* kAoScene = "AO, default";

struct AoSetting {
  std::string technique, family;
  std::vector<std::pair<std::string, std::string>> sets;
};

std::vector<AoSetting> ao_settings(bool quick) {
  std::vector<AoSetting> out;
  const std::vector<int> samples = quick ? std::vector<int>{8, 32} : std::vector<int>{8, 16, 32, 64};
  for (const bool blur : {false, true})
    for (const int n : samples)
      out.push_back({"ssao " + std::to_string(n) + (blur ? " blur" : ""), blur ? "SSAO, blurred" : "SSAO",
                     {{"ssao.method", "ssao"}, {"ssao.samples", std::to_string(n)}, {"ssao.blur", blur ? "1" : "0"}}});
  const std::vector<std::pair<int, int>> gtao =
      quick ? std::vector<std::pair<int, int>>{{2, 4}, {4, 8}}
            : std::vector<std::pair<int, int>>{{1, 4}, {2, 4}, {2, 8}, {4, 8}, {4, 16}, {8, 16}};
  for (const auto& [directions, steps] : gtao)
    out.push_back({"gtao " + std::to_string(directions) + "x" + std::to_string(steps) + " blur", "GTAO, blurred",
                   {{"ssao.method", "gtao"},
                    {"ssao.gtao_directions", std::to_string(directions)},
                    {"ssao.gtao_steps", std::to_string(steps)},
                    {"ssao.blur", "1"}}});
  return out;
}

bool is_ao_pass(std::string_view name) { return name.starts_with("ssao") || name.starts_with("gtao"); }

}  // namespace

nlohmann::json measure_ao_front(Renderer& renderer, bool quick) {
  const Lab& lab = *find_lab(17);
  if (!renderer.set_features(lab.hooks(Impl::Solution))) throw std::runtime_error(renderer.shader_error());
  renderer.set_scene(make_default_scene());
  FrameRequest request = bench_request(ao_view_bounds(renderer.scene()));  // yaw and pitch 30: lab 17's view
  const int frames = quick ? 3 : 7;
  ParamSet base = lab_params(lab);
  for (const ParamSpec& spec : ao_method_param_specs()) base.declare(spec);
  base.set("view.debug_quad", 0.0);
  base.set("ssao.radius", kAoRadius);

  // The truth, once: every point draws the same G-buffer (one scene, one camera).
  request.gbuffer = true;
  renderer.render(base, request);
  const GBuffer gbuffer = renderer.read_gbuffer();
  const Oracle oracle(ao_occluders(renderer.scene()));
  const AoTruth truth = evaluate_ao(oracle, gbuffer, kAoRadius);
  request.gbuffer = false;

  nlohmann::json points = nlohmann::json::array();
  for (const AoSetting& setting : ao_settings(quick)) {
    ParamSet params = base;
    for (const auto& [key, value] : setting.sets) params.set_from_string(key, value);
    std::map<std::string, std::vector<double>> pass_ms;
    for (int frame = -1; frame < frames; ++frame) {
      const FrameStats& stats = renderer.render(params, request);
      if (frame < 0) continue;  // warm-up: shader variants, allocations
      for (const auto& p : stats.passes)
        if (is_ao_pass(p.name)) pass_ms[std::string(p.name)].push_back(p.gpu_ms);
    }
    nlohmann::json medians = nlohmann::json::object();
    double gpu_ms = 0.0;
    for (auto& [name, v] : pass_ms) gpu_ms += (medians[name] = median(v)).get<double>();
    request.gbuffer = true;
    renderer.render(params, request);
    request.gbuffer = false;
    const AoInteriorError e = ao_interior_error(renderer.read_gbuffer(), renderer.read_ao(true), truth, kAoRadius);
    nlohmann::json point = {{"scene", kAoScene},
                            {"technique", setting.technique},
                            {"family", setting.family},
                            {"map_size", 0},
                            {"gpu_ms", gpu_ms},
                            {"pass_ms", medians},
                            {"error", e.mean},
                            {"signed_error", e.mean_signed},
                            {"open_error", e.open},
                            {"occluded_error", e.occluded},
                            {"interior_pixels", e.interior_pixels}};
    for (const auto& [key, value] : setting.sets) point[key] = value;
    points.push_back(point);
  }
  const BenchPlots plots = bench_plots_from_json({{"points", points}});
  const auto& plot = plots.by_scene.at(kAoScene);
  for (std::size_t i = 0; i < points.size(); ++i) points[i]["pareto"] = plot[i].pareto;
  return {{"resolution", {request.width, request.height}},
          {"radius", kAoRadius},
          {"frames_per_point", frames},
          {"truth_seconds", truth.seconds},
          {"truth_rays", truth.rays},
          {"error", "mean |AO - truth| over the interior (oracle/ao_metrics.h); gpu_ms: the AO passes' medians"},
          {"points", points}};
}

void print_ao_front(const nlohmann::json& ao) {
  std::vector<const nlohmann::json*> front;
  for (const auto& p : ao.at("points"))
    if (p.at("pareto").get<bool>()) front.push_back(&p);
  std::sort(front.begin(), front.end(),
            [](const nlohmann::json* a, const nlohmann::json* b) { return a->at("gpu_ms") < b->at("gpu_ms"); });
  std::printf("front, %s:", kAoScene);
  for (const auto* p : front)
    std::printf("  %s (%.1f ms, %.4f)", p->at("technique").get<std::string>().c_str(), p->at("gpu_ms").get<double>(),
                p->at("error").get<double>());
  std::printf("\n");
}

}  // namespace shadowlab
