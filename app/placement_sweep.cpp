#include "app/placement_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/technique_params.h"
#include "core/vsm_params.h"
#include "labs/registry.h"

namespace shadowlab {

std::vector<PlacementTechnique> placement_techniques() {
  return {
      {"depth map, directional (lab 1)", "bias_tuning", {}},
      {"fitted ortho box (lab 2, C++)", "ortho_fit", {}},
      {"PCF 3x3 (lab 6)", "pcf", {}},
      {"VSM, blurred r2 (lab 5)", "moment_blur", {"vsm.blur_radius=2"}},
      {"EVSM (lab 13)", "evsm", {}},
      {"MSM (lab 14)", "msm", {}},
      {"cascaded shadow maps (lab 12, C++)", "cascaded_shadow_maps", {}},
      {"spot light (lab 7)", "spot_light", {}},
      {"point light, cube (lab 8)", "point_light", {}},
      {"shadow volumes, directional (lab 9)", "shadow_volumes", {"light.type=directional"}},
      {"shadow volumes, point (lab 9)", "shadow_volumes", {"light.type=point"}},
  };
}

const Lab& placement_lab(const PlacementTechnique& technique) {
  const Lab* lab = find_lab_named(technique.lab);
  if (!lab) throw std::invalid_argument("placement technique \"" + technique.name + "\": no lab is named " + technique.lab);
  return *lab;
}

namespace {
std::string label(const char* what, double value) {
  char s[64];
  std::snprintf(s, sizeof s, "%s %.0e", what, value);
  return s;
}
}  // namespace

std::vector<PlacementPoint> placement_grid(bool sampled) {
  std::vector<PlacementPoint> grid;
  const std::pair<const char*, glm::dvec3> axes[] = {{"x", {1, 0, 0}}, {"y", {0, 1, 0}}, {"z", {0, 0, 1}}, {"-x+y-z", {-1, 1, -1}}};
  const double offsets[] = {1e3, 1e4, 1e5, 1e6, 1e7};
  for (std::size_t a = 0; a < 4; ++a)
    for (std::size_t k = 0; k < 5; ++k) {
      // Sampled: each axis once, the decades spread over the axes, 1e7 on two of them.
      if (sampled && !(k == a + 1 || (k == 4 && a == 0))) continue;
      PlacementPoint p{label(axes[a].first, offsets[k]), {}};
      p.placement.offset = axes[a].second * offsets[k];
      grid.push_back(p);
    }
  for (int e = -4; e <= 5; ++e) {
    if (sampled && e != -4 && e != 5) continue;
    PlacementPoint p{label("scale", std::pow(10.0, e)), {}};
    p.placement.scale = std::pow(10.0, e);
    grid.push_back(p);
  }
  for (double scale : {1e-4, 1e5}) {
    if (sampled && scale > 1.0) continue;
    PlacementPoint p{label("-x+y-z 1e7, scale", scale), {}};
    p.placement.offset = glm::dvec3(-1e7, 1e7, -1e7);
    p.placement.scale = scale;
    grid.push_back(p);
  }
  return grid;
}

std::vector<std::string> placement_assignments(const Placement& placement) {
  auto number = [](double v) {
    char s[64];
    std::snprintf(s, sizeof s, "%.17g", v);
    return std::string(s);
  };
  return {"scene.offset_x=" + number(placement.offset.x), "scene.offset_y=" + number(placement.offset.y),
          "scene.offset_z=" + number(placement.offset.z), "scene.scale=" + number(placement.scale),
          std::string("scene.local_origin=") + (placement.local_origin ? "true" : "false")};
}

PlacementOutcome measure_placement(CheckContext& ctx, const PlacementTechnique& technique, const Placement& placement,
                                   int width, int height) {
  ParamSet p = ctx.params();
  p.set("view.debug_quad", 0.0);
  for (const auto& a : technique.assignments) {
    const std::string key = a.substr(0, a.find('='));
    if (!p.find(key) && key.rfind("vsm.", 0) == 0) p.declare(vsm_param_specs({key}).at(0));
    p.apply_assignment(a);
  }
  for (const auto& a : placement_assignments(placement)) p.apply_assignment(a);
  const auto m = ctx.measure(p, ctx.lab.hooks(Impl::Solution), "placement", nullptr, grading_band(), width, height);
  PlacementOutcome o;
  o.error = m.metrics.acne_rate_all + m.metrics.leak_rate_all;
  o.graded = static_cast<double>(m.metrics.valid_pixels);
  for (float v : m.visibility)
    if (!std::isfinite(v)) ++o.non_finite;
  return o;
}

PlacementSweep sweep_placements(const PlacementTechnique& technique, const std::vector<PlacementPoint>& grid, int width,
                                int height) {
  const Scene scene = make_default_scene();  // the context keeps a reference
  Renderer renderer;
  CheckContext ctx(renderer, placement_lab(technique), Impl::Solution, scene, {});
  PlacementSweep sweep;
  sweep.origin = measure_placement(ctx, technique, Placement{}, width, height);
  sweep.non_finite = sweep.origin.non_finite;
  for (const PlacementPoint& point : grid) {
    const PlacementOutcome o = measure_placement(ctx, technique, point.placement, width, height);
    double& worst = point.placement.scale == 1.0 ? sweep.worst_offset : sweep.worst_scale;
    worst = std::max(worst, std::abs(o.error - sweep.origin.error));
    sweep.non_finite += o.non_finite;
    sweep.points.push_back(o);
  }
  Placement naive;
  naive.offset = glm::dvec3(-1e6, 1e6, -1e6);
  naive.local_origin = false;
  sweep.error_1e6_without_local_origin = measure_placement(ctx, technique, naive, width, height).error;
  return sweep;
}

}  // namespace shadowlab
