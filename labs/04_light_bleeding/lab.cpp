// Lab 4: VSM's light bleeding and its fix (the course's task 5: bias and the remap of the bound).
// Demonstrates: why Chebyshev's bound lets light through stacked occluders, the remap
// [0, delta] -> 0, [delta, 1] -> [0, 1] that cuts it, the price (darker, narrower penumbrae), and a
// debug view tinting the pixels the remap changed. Check: on the stacked-occluder scene, the bleeding
// rate against the oracle with the student's delta against lab 3's unfixed test, the acne rate, and a
// sweep of delta; the default scene is measured and reported.
#include "labs/lab.h"

#include <cstdio>
#include <utility>

#include "labs/check.h"
#include "renderer/vsm_params.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = "labs/04_light_bleeding/exercise.glsl";
constexpr const char* kSolution = "shaders/vsm/visibility.glsl";       // the renderer's own VSM test
constexpr const char* kUnfixed = "labs/03_vsm_setup/visibility.glsl";  // lab 3's test: no bias, no remap

// The targets: the fix must remove at least three quarters of the bleeding, and leave at most
// 1 % of the interior shadow bleeding, without making more than 0.5 % of the lit interior shadowed.
constexpr double kMaxBleedingRatio = 0.25;
constexpr double kMaxBleeding = 0.01;
constexpr double kMaxAcne = 0.005;
// The blurred case: lab 5's kernel at radius 4 (sigma 2), where the unfixed bleeding exceeds 1 %.
constexpr int kBlurRadius = 4;
constexpr double kBlurSigma = 2.0;
constexpr double kSweep[] = {0.0, 0.025, 0.05, 0.1, 0.125, 0.15, 0.2, 0.3, 0.4, 0.5};

// The region where the occluders' shadows fall on the receiver (y = 0), so the camera spends its pixels
// on the overlaps where bleeding happens rather than on open ground.
Bounds shadows_on_receiver(const Scene& scene, const glm::vec3& to_light) {
  Bounds b;
  for (const auto& mesh : scene.meshes) {
    if (mesh.name == "receiver") continue;
    const Bounds m = mesh.bounds();
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 c = m.corner(i);
      b.extend(glm::vec3(c.x, 0.0f, c.z));
      b.extend(c - to_light * (c.y / to_light.y));
    }
  }
  return b;
}

void check_light_bleeding(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  params.set("vsm.show_remap", 0.0);
  const LabHooks hooks = ctx.hooks();
  LabHooks unfixed = hooks;
  unfixed.includes["lab/visibility.glsl"] = kUnfixed;

  // 1. The default scene, reported: the fix must not hurt an ordinary scene.
  const auto d = ctx.measure(params, hooks, std::string("lab04_default_") + impl_name(ctx.impl));
  result.metrics["default_scene"] = to_json(d.metrics);

  // 2. The stacked occluders: lab 3's unfixed test, then the student's fix, at the lab's settings and
  // with the moments blurred (lab 5's 9x9 Gaussian), where bleeding spreads over many more pixels.
  ctx.use_scene(make_stacked_occluders_scene());
  const Bounds view = shadows_on_receiver(
      ctx.scene(), direction_from_angles(params.get_float("light.azimuth"), params.get_float("light.elevation")));
  ParamSet blurred = params;
  blurred.set("vsm.blur_radius", kBlurRadius);
  blurred.set("vsm.blur_sigma", kBlurSigma);
  const std::pair<std::string, const ParamSet*> cases[] = {{"stacked", &params}, {"stacked_blur4", &blurred}};
  for (const auto& [tag, p] : cases) {
    const auto u = ctx.measure(*p, unfixed, "lab04_" + tag + "_unfixed", &view);
    const auto m = ctx.measure(*p, hooks, "lab04_" + tag + "_" + impl_name(ctx.impl), &view);
    result.metrics[tag + "_unfixed"] = to_json(u.metrics);
    result.metrics[tag] = to_json(m.metrics);
    const double ratio = u.metrics.bleeding_rate > 0 ? m.metrics.bleeding_rate / u.metrics.bleeding_rate : 1.0;
    result.criteria.push_back({tag + ".bleeding_ratio_to_unfixed", ratio, Criterion::kAtMost, kMaxBleedingRatio,
                               "issue: at most 1/4 of lab 3's bleeding"});
    result.criteria.push_back(
        {tag + ".bleeding_rate", m.metrics.bleeding_rate, Criterion::kAtMost, kMaxBleeding, "issue target 1 %"});
    result.criteria.push_back(
        {tag + ".acne_rate", m.metrics.acne_rate, Criterion::kAtMost, kMaxAcne, "issue target 0.5 %"});
  }

  // 3. The sweep, blurred: bleeding against over-darkening (acne, and the mean error in the edge band)
  // per delta, with the lab's own test (so the exercise shows that delta does nothing before the remap).
  nlohmann::json sweep = nlohmann::json::array();
  std::printf("    delta sweep (stacked scene, blur radius %d, %s):\n", kBlurRadius, impl_name(ctx.impl));
  std::printf("      delta  bleeding  acne     leak     mae_interior  mae_edge\n");
  const auto out_dir = std::exchange(ctx.out_dir, {});  // the sweep writes no pictures
  for (double delta : kSweep) {
    ParamSet p = blurred;
    p.set("vsm.bleed_delta", delta);
    const auto s = ctx.measure(p, hooks, "", &view);
    sweep.push_back({{"delta", delta},
                     {"bleeding_rate", s.metrics.bleeding_rate},
                     {"acne_rate", s.metrics.acne_rate},
                     {"leak_rate", s.metrics.leak_rate},
                     {"mae_interior", s.metrics.mae_interior},
                     {"mae_edge", s.metrics.mae_edge}});
    std::printf("      %5.3f  %7.4f  %7.4f  %7.4f  %8.5f      %8.5f\n", delta, s.metrics.bleeding_rate,
                s.metrics.acne_rate, s.metrics.leak_rate, s.metrics.mae_interior, s.metrics.mae_edge);
  }
  ctx.out_dir = out_dir;
  result.metrics["delta_sweep"] = sweep;
}

}  // namespace

Lab make_lab_light_bleeding() {
  Lab lab;
  lab.number = 4;
  lab.slug = "light_bleeding";
  lab.title = "VSM: bias and light bleeding";
  lab.summary = "Cut the light that bleeds through stacked occluders: bias z, remap [0, delta] to 0.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSet base(renderer_param_specs());
  ParamSpec bias = *base.find("shadow.bias"), slope = *base.find("shadow.slope_bias");
  bias.default_value = 0.0005;
  slope.default_value = 0.0;
  lab.params = {bias, slope};
  for (auto& spec :
       vsm_param_specs({"vsm.min_variance", "vsm.bleed_delta", "vsm.show_remap", "vsm.blur_radius", "vsm.blur_sigma"}))
    lab.params.push_back(spec);
  lab.presets = {
      {"no fix", "delta = 0 and no bias: lab 3's result.", {{"vsm.bleed_delta", "0"}, {"shadow.bias", "0"}}},
      {"course", "delta = 0.125, as in the course.", {{"vsm.bleed_delta", "0.125"}}},
      {"too much", "delta = 0.5: no bleeding, but penumbrae shrink and darken.", {{"vsm.bleed_delta", "0.5"}}},
      {"show remap", "Tint the pixels the remap changed.", {{"vsm.show_remap", "true"}}},
  };
  lab.offered_includes = {"lab/bias.glsl", "lab/chebyshev.glsl"};
  lab.make_hooks = [](const SlotFiles& files) {
    LabHooks hooks;
    hooks.technique = ShadowTechnique::Moments;
    hooks.includes["lab/visibility.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_light_bleeding;
  return lab;
}

}  // namespace shadowlab
