// Lab 0: the basic shadow map, the starting point before the numbered exercises.
// Demonstrates: a depth-only pass from the light, the [-1,1] -> [0,1] bias matrix, one depth comparison
// per fragment with a constant bias, and the debug quad showing the shadow map.
// Check: the default scene under the default light (azimuth 35, elevation 50) at the renderer's fixed
// bias 0.005: acne and leak over interior pixels within lab 1's bounds.
#include "labs/check.h"
#include "labs/lab.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = "labs/00_basic_shadow_map/exercise.glsl";
constexpr const char* kSolution = "labs/00_basic_shadow_map/solution.glsl";

// Lab 1's bounds (the targets for a tuned bias); measured figures are in the README.
constexpr double kMaxAcne = 0.001;
constexpr double kMaxLeak = 0.005;

void check_basic(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const auto m = ctx.measure(params, ctx.hooks(), std::string("lab00_") + impl_name(ctx.impl));
  result.metrics = to_json(m.metrics);
  result.metrics["interior_agreement"] = interior_agreement(m.metrics);
  result.metrics["render_ms"] = m.render_ms;
  result.metrics["oracle_ms"] = m.oracle_ms;
  result.criteria = {
      {"acne_rate", m.metrics.acne_rate, Criterion::kAtMost, kMaxAcne, "lab 1's bound, 0.1 % of lit interior"},
      {"leak_rate", m.metrics.leak_rate, Criterion::kAtMost, kMaxLeak, "lab 1's bound, 0.5 % of shadowed interior"},
  };
}

}  // namespace

Lab make_lab_basic_shadow_map() {
  Lab lab;
  lab.number = 0;
  lab.slug = "basic_shadow_map";
  lab.title = "Basic shadow map";
  lab.summary = "Two passes: depth from the light, then one depth comparison per pixel.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.presets = {
      {"acne", "No bias: surfaces shadow themselves in stripes.", {{"shadow.bias", "0"}}},
      {"peter-panning", "A huge bias: shadows detach from the objects casting them.", {{"shadow.bias", "0.05"}}},
      {"tutorial", "The tutorial's constant bias of 0.005.", {{"shadow.bias", "0.005"}}},
  };
  lab.offered_includes = {"lab/bias.glsl"};
  lab.make_hooks = visibility_lab_hooks();
  lab.check = check_basic;
  return lab;
}

}  // namespace shadowlab
