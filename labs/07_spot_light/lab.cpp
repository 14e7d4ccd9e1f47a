// Lab 7: a spot light (the flashlight task).
// Demonstrates: a perspective shadow projection from the light's position with the cone's angle, near
// and far fitted to the scene's box (fit_spot_light), and a bias that works with perspective depth:
// linearised depths and a bias in world units that grows with a texel's footprint. Check: the default
// scene lit by the spot from two places (high and far, low and near), against the oracle casting toward
// the light's position; pixels outside the cone are not graded.
#include <cstdio>

#include "labs/check.h"
#include "labs/lab.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = "labs/07_spot_light/exercise.glsl";
constexpr const char* kSolution = "shaders/shadow/spot.glsl";  // the renderer's own spot test

// Lab 1's bounds over interior pixels.
constexpr double kMaxAcne = 0.001;
constexpr double kMaxLeak = 0.005;

struct SpotPlace {
  const char* tag;
  float x, y, z, cone_deg;
};
// High and far: depth spans a narrow slice of [near, far]. Low and near: the near plane is close, depth
// crowds toward 1 across the scene.
constexpr SpotPlace kPlaces[] = {{"high", 5.0f, 7.0f, 4.0f, 40.0f}, {"low", -4.0f, 2.0f, 3.5f, 60.0f}};

void check_spot(CheckContext& ctx, CheckResult& result) {
  const LabHooks hooks = ctx.hooks();
  for (const auto& place : kPlaces) {
    ParamSet p = ctx.params();
    p.set("view.debug_quad", 0.0);
    p.set("light.position_x", place.x);
    p.set("light.position_y", place.y);
    p.set("light.position_z", place.z);
    p.set("light.cone_deg", place.cone_deg);
    const std::string tag = place.tag;
    const auto m = ctx.measure(p, hooks, "lab07_" + tag + "_" + impl_name(ctx.impl));
    const glm::mat4& proj = ctx.renderer.light_view().projection;
    const float near_plane = proj[3][2] / (proj[2][2] - 1.0f), far_plane = proj[3][2] / (proj[2][2] + 1.0f);
    result.metrics[tag] = to_json(m.metrics);
    result.metrics[tag]["interior_agreement"] = interior_agreement(m.metrics);
    result.metrics[tag]["light"] = {{"position", {place.x, place.y, place.z}}, {"cone_deg", place.cone_deg},
                                    {"near", near_plane}, {"far", far_plane}};
    std::printf("    %s: near %.3f far %.3f  acne %.5f leak %.5f (interior), %llu graded pixels\n", place.tag, near_plane,
                far_plane, m.metrics.acne_rate, m.metrics.leak_rate,
                static_cast<unsigned long long>(m.metrics.valid_pixels));
    result.criteria.push_back({tag + ".acne_rate", m.metrics.acne_rate, Criterion::kAtMost, kMaxAcne, "lab 1's bound"});
    result.criteria.push_back({tag + ".leak_rate", m.metrics.leak_rate, Criterion::kAtMost, kMaxLeak, "lab 1's bound"});
  }
}

}  // namespace

Lab make_lab_spot_light() {
  Lab lab;
  lab.number = 7;
  lab.slug = "spot_light";
  lab.title = "Spot light: perspective shadow map";
  lab.summary = "A flashlight: perspective projection from the light's position, near/far fitted, bias in world units.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSet base(renderer_param_specs());
  ParamSpec slope = *base.find("shadow.slope_bias");
  slope.default_value = 2.0;
  lab.params = {slope};
  for (auto spec : technique_param_specs({"light.position_x", "light.position_y", "light.position_z", "light.cone_deg"})) {
    if (spec.key == "light.position_x") spec.default_value = kPlaces[0].x;
    if (spec.key == "light.position_y") spec.default_value = kPlaces[0].y;
    if (spec.key == "light.position_z") spec.default_value = kPlaces[0].z;
    if (spec.key == "light.cone_deg") spec.default_value = kPlaces[0].cone_deg;
    lab.params.push_back(spec);
  }
  lab.presets = {
      {"high", "High and far: the check's first place.", {{"light.position_x", "5"}, {"light.position_y", "7"}, {"light.position_z", "4"}, {"light.cone_deg", "40"}}},
      {"low", "Low and near: the check's second place.", {{"light.position_x", "-5.5"}, {"light.position_y", "3.2"}, {"light.position_z", "3"}, {"light.cone_deg", "50"}}},
      {"narrow", "A 15-degree cone: the same texels on a small spot, crisp shadows.", {{"light.cone_deg", "15"}}},
  };
  lab.offered_includes = {"lab/bias.glsl"};
  lab.make_hooks = visibility_lab_hooks(LightType::Spot);
  lab.check = check_spot;
  return lab;
}

}  // namespace shadowlab
