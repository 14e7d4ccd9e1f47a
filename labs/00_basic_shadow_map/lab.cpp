// Lab 0: the basic shadow map, the starting point before the numbered exercises.
// Demonstrates: a depth-only pass from the light, the [-1,1] -> [0,1] bias matrix, one depth comparison
// per fragment with a constant bias, and the debug quad showing the shadow map.
// Check: the default scene under the default light (azimuth 35, elevation 50) at the renderer's fixed
// bias 0.005, then three held-out lights, map sizes and scenes: the continuous acne and leak errors over
// interior pixels within lab 1's bounds in every case.
#include "labs/check.h"
#include "labs/lab.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = "labs/00_basic_shadow_map/exercise.glsl";
constexpr const char* kSolution = "labs/00_basic_shadow_map/solution.glsl";

// The lab's constant bias (0.005 in depth units of the fitted box) keeps acne away down to about 30
// degrees on the built-in scenes; held-out lights stay above that (lab 1 is where low lights are graded).
const std::vector<HeldOutRange> kHeldOut = {{30.0f, 50.0f, {"512", "1024", "2048"}, {"default", "stacked"}},
                                            {50.0f, 70.0f, {"512", "1024", "2048"}, {"default", "stacked"}},
                                            {70.0f, 88.0f, {"512", "1024", "2048"}, {"default", "stacked"}}};

const char* kAdvice =
    "map the light's clip coordinates from [-1, 1] to [0, 1] (x, y and z) before reading the map and comparing.";

void check_basic(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const LabHooks hooks = ctx.hooks();
  HardLimits limits;
  // 1. The lab's own scene and light.
  const auto m = ctx.measure(params, hooks, std::string("lab00_") + impl_name(ctx.impl));
  grade_hard_shadow(result, "lab_light", m.metrics, limits);
  result.metrics["lab_light"]["render_ms"] = m.render_ms;
  result.metrics["lab_light"]["oracle_ms"] = m.oracle_ms;
  // 2. Held-out lights, map sizes and scenes: the bias matrix is the same for every one.
  for (const auto& c : draw_directional_cases(ctx, kHeldOut)) {
    const auto h = ctx.measure(c.apply(ctx, params), hooks, "lab00_" + c.tag + "_" + impl_name(ctx.impl));
    grade_hard_shadow(result, c.tag, h.metrics, limits);
    result.conditions.push_back(c.to_json());
  }
  ctx.use_default_scene();
  for (auto& c : result.criteria)
    if (c.metric.ends_with("_error")) c.advice = kAdvice;
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
