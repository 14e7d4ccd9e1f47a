#include "app/bench_placement.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/bench_figures.h"
#include "app/exit_codes.h"
#include "app/command_options.h"
#include "app/placement_sweep.h"
#include "labs/registry.h"
#include "renderer/context.h"
#include "renderer/gl.h"
#include "core/gltf_loader.h"
#include "core/image_io.h"
#include "core/platform.h"
#include "renderer/shader.h"

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

constexpr int kPlacementWidth = 480, kPlacementHeight = 270;  // as the CI test (tests/test_gl_stress.cpp)

// The grid for one technique: the error at each point, the worst difference from the origin's over the
// offsets and over the scales, and the error without the local origin at 1e6 on the diagonal.
nlohmann::json sweep_technique(const PlacementTechnique& t, const std::vector<PlacementPoint>& grid) {
  const PlacementSweep sweep = sweep_placements(t, grid, kPlacementWidth, kPlacementHeight);
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 0; i < grid.size(); ++i)
    points.push_back({{"placement", grid[i].label},
                      {"error", sweep.points[i].error},
                      {"difference", std::abs(sweep.points[i].error - sweep.origin.error)}});
  return {{"technique", t.name},
          {"lab", placement_lab(t).number},
          {"error_at_origin", sweep.origin.error},
          {"worst_difference_offsets", sweep.worst_offset},
          {"worst_difference_scales", sweep.worst_scale},
          {"error_1e6_without_local_origin", sweep.error_1e6_without_local_origin},
          {"non_finite", sweep.non_finite},
          {"points", points}};
}

// Frames of lab 1's solution at 1280x720 in three configurations, in alternating blocks (the first frame
// after a switch converts and uploads the scene: timed on its own): the default scene moved 1e6 along the
// diagonal with the local origin and without it, and the scene at the origin (where the local origin
// changes nothing). Without the local origin the picture is not the same one (acne, jagged edges), so
// the overhead of the conversion is read against the origin's frame, the same picture. Each frame
// redraws the shadow map (the camera turns a little), glFinish included.
nlohmann::json frame_cost(int frames, int rounds) {
  Renderer renderer;
  const Lab* hard = find_lab_offering("hard");  // lab 1's solution: the hard shadow, with its slope bias
  if (!hard) throw std::runtime_error("the frame-cost figure needs a lab offering \"hard\" to the bench");
  const Lab& lab = *hard;
  const Scene scene = make_default_scene();
  renderer.set_scene(scene);
  if (!renderer.set_features(lab.hooks(Impl::Solution))) throw std::runtime_error(renderer.shader_error());
  ParamSet params = lab_params(lab);
  params.set("view.debug_quad", 0.0);
  FrameRequest request;
  request.width = 1280;
  request.height = 720;
  const OrbitCamera framing = OrbitCamera::framing(scene.bounds());
  enum Config { kWith, kWithout, kOrigin, kConfigs };
  const char* names[kConfigs] = {"with_local_origin", "without_local_origin", "at_the_origin"};
  auto configure = [&](int config) {
    const double offset = config == kOrigin ? 0.0 : 1e6;
    params.set("scene.offset_x", -offset);
    params.set("scene.offset_y", offset);
    params.set("scene.offset_z", -offset);
    params.set("scene.local_origin", config == kWithout ? 0.0 : 1.0);
  };
  std::vector<double> frame_ms[kConfigs], switch_ms[kConfigs];
  auto timed = [&] {
    const auto start = std::chrono::steady_clock::now();
    renderer.render(params, request);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  for (int r = 0; r < rounds + 1; ++r)  // round 0 warms up
    for (int config = 0; config < kConfigs; ++config) {
      configure(config);
      request.camera = framing;
      const double first = timed();
      if (r > 0) switch_ms[config].push_back(first);
      for (int f = 0; f < frames; ++f) {
        request.camera.yaw_deg += 1.0f;
        renderer.invalidate_shadow_map();
        const double wall = timed();
        if (r > 0) frame_ms[config].push_back(wall);
      }
    }
  // The conversion alone, on the CPU: the default scene and the PalmTree (10k triangles).
  auto conversion_ms = [](const Scene& s) {
    Placement p;
    p.offset = glm::dvec3(-1e6, 1e6, -1e6);
    std::vector<double> ms;
    for (int i = 0; i < 9; ++i) {
      const auto start = std::chrono::steady_clock::now();
      const Scene local = local_scene(s, p);
      ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      if (local.meshes.size() != s.meshes.size()) throw std::logic_error("local_scene lost meshes");
    }
    return median(ms);
  };
  const Scene palm = load_gltf(data_dir() / "assets" / "models" / "PalmTree" / "PalmTree.gltf");
  nlohmann::json out = {{"frames_per_block", frames}, {"rounds", rounds}, {"size", "1280x720"}};
  for (int config = 0; config < kConfigs; ++config)
    out[names[config]] = {{"frame_ms", median(frame_ms[config])}, {"first_frame_after_switch_ms", median(switch_ms[config])}};
  out["ratio_with_to_without"] = median(frame_ms[kWith]) / median(frame_ms[kWithout]);
  out["ratio_with_to_origin"] = median(frame_ms[kWith]) / median(frame_ms[kOrigin]);
  out["conversion_ms"] = {{"default_scene", conversion_ms(scene)}, {"palm_tree", conversion_ms(palm)}};
  out["palm_tree_triangles"] = palm.triangle_count();
  return out;
}

}  // namespace

int run_placement_bench(const BenchOptions& options) {
  bool usage_checked = false;
  try {
    make_output_dir(options.out_dir);
    usage_checked = true;
    std::string error;
    auto context = HeadlessContext::create(&error);
    if (!context) throw std::runtime_error(error);
    const std::vector<PlacementPoint> grid = placement_grid(options.quick);
    nlohmann::json rows = nlohmann::json::array();
    std::printf("Every technique at offsets 1e3..1e7 (+x, +y, +z, -x+y-z) and scales 1e-4..1e5 (%zu placements, %dx%d), "
                "error = acne + leak against the oracle:\n\n",
                grid.size(), kPlacementWidth, kPlacementHeight);
    std::printf("| technique | error at the origin | worst difference, offsets | worst difference, scales | error at 1e6 without the local origin |\n");
    std::printf("|---|---|---|---|---|\n");
    for (const PlacementTechnique& t : placement_techniques()) {
      const nlohmann::json row = sweep_technique(t, grid);
      std::printf("| %s | %.4f | %.1e | %.1e | %.3f |\n", t.name.c_str(), row["error_at_origin"].get<double>(),
                  row["worst_difference_offsets"].get<double>(), row["worst_difference_scales"].get<double>(),
                  row["error_1e6_without_local_origin"].get<double>());
      std::fflush(stdout);
      rows.push_back(row);
    }
    const nlohmann::json cost = frame_cost(options.quick ? 5 : 15, options.quick ? 2 : 4);
    std::printf("\nFrame cost, lab 1 at 1280x720, shadow map redrawn every frame (median of %d frames each, "
                "alternating blocks in one run):\n",
                cost["frames_per_block"].get<int>() * cost["rounds"].get<int>());
    const std::pair<const char*, const char*> lines[] = {
        {"with_local_origin", "scene at 1e6 (diagonal), local origin on "},
        {"without_local_origin", "scene at 1e6 (diagonal), local origin off"},
        {"at_the_origin", "scene at the origin (the same picture as on)"}};
    for (const auto& [key, label] : lines)
      std::printf("  %-46s %.2f ms, first frame after switching to it %.2f ms\n", label, cost[key]["frame_ms"].get<double>(),
                  cost[key]["first_frame_after_switch_ms"].get<double>());
    std::printf("  ratio on / off           %.3f (off draws another picture: acne, jagged edges)\n",
                cost["ratio_with_to_without"].get<double>());
    std::printf("  ratio on / at the origin %.3f (the conversion's own cost per frame)\n", cost["ratio_with_to_origin"].get<double>());
    std::printf("  converting the scene to the local frame (CPU, once per placement): default scene %.3f ms, PalmTree (%zu triangles) %.3f ms\n",
                cost["conversion_ms"]["default_scene"].get<double>(), cost["palm_tree_triangles"].get<std::size_t>(),
                cost["conversion_ms"]["palm_tree"].get<double>());
    const nlohmann::json out = {{"grid", options.quick ? "sampled" : "full"}, {"placements", grid.size()}, {"techniques", rows}, {"frame_cost", cost}};
    write_text_atomic(fs::path(options.out_dir) / "placement.json", out.dump(2) + "\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadowlab bench --placement: %s\n", e.what());
    return usage_checked ? kExitRuntime : kExitUsage;
  }
}

}  // namespace shadowlab
