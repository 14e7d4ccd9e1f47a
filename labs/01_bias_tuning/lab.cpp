// Lab 1: bias tuning, acne against peter-panning.
// Demonstrates: why a constant bias fails at grazing light, a slope-scaled bias in texels, and culling
// front faces in the shadow pass. Check: the default scene under a grazing light (elevation 10 deg).
#include <filesystem>
#include <fstream>
#include <regex>

#include "labs/check.h"
#include "labs/lab.h"

namespace shadowlab {

namespace {

// The culling the student chose with `#define SHADOW_PASS_CULL ...` in the exercise file: 0 none,
// 1 front, 2 back (the order of the shadow.cull parameter's choices). Re-read when the file changes.
class CullDirective {
 public:
  explicit CullDirective(std::filesystem::path file) : file_(std::move(file)) {}
  int operator()() {
    std::error_code ec;
    const auto path = data_dir() / file_;
    const auto time = std::filesystem::last_write_time(path, ec);
    if (ec || time == seen_) return cull_;
    seen_ = time;
    std::ifstream in(path);
    static const std::regex re(R"(^\s*#\s*define\s+SHADOW_PASS_CULL\s+(NONE|FRONT|BACK)\b)");
    cull_ = 0;
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (std::regex_search(line, m, re)) cull_ = m[1] == "FRONT" ? 1 : m[1] == "BACK" ? 2 : 0;
    }
    return cull_;
  }

 private:
  std::filesystem::path file_;
  std::filesystem::file_time_type seen_{};
  int cull_ = 0;
};

constexpr const char* kExercise = "labs/01_bias_tuning/exercise.glsl";
constexpr const char* kSolution = "labs/01_bias_tuning/solution.glsl";

// A constant that works at one light and one map size fails at another: the held-out cases span low
// and high lights (the depth change across one texel grows with tan(angle of incidence)) and coarse and
// fine maps (a texel's size), on both built-in scenes. The lowest light stays above 6 degrees: below
// 5.7 the ground itself is lit beyond 84 degrees of incidence, which no check grades (grading_band());
// below 15 degrees the stacked scene's shadows leave its receiver, so only the default scene is used.
const std::vector<HeldOutRange> kHeldOut = {{6.0f, 9.0f, {"512", "1024"}, {"default"}},
                                            {9.0f, 20.0f, {"256", "512", "1024", "2048"}, {"default"}},
                                            {20.0f, 45.0f, {"256", "512", "1024", "2048"}, {"stacked", "default"}},
                                            {45.0f, 80.0f, {"256", "512", "1024", "2048"}, {"stacked", "default"}}};

void check_bias(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("light.elevation", 10.0);  // grazing light: where a constant bias breaks down
  params.set("view.debug_quad", 0.0);
  const LabHooks hooks = ctx.hooks();
  const HardLimits limits;
  const auto m = ctx.measure(params, hooks, "lab01_grazing");
  grade_hard_shadow(result, "grazing", m.metrics, limits);
  result.metrics["grazing"]["render_ms"] = m.render_ms;
  result.metrics["grazing"]["oracle_ms"] = m.oracle_ms;
  for (const auto& c : draw_directional_cases(ctx, kHeldOut)) {
    const auto h = ctx.measure(c.apply(ctx, params), hooks, "lab01_" + c.tag);
    grade_hard_shadow(result, c.tag, h.metrics, limits);
    result.conditions.push_back(c.to_json());
  }
  ctx.use_default_scene();
  for (auto& c : result.criteria) {
    if (c.metric.ends_with(".lit_error"))
      c.advice = "acne: the bias is too small for this light or map size. Make it grow with the slope (tan of the angle "
                 "of incidence) and with the texel's size (u_texel_depth), not a constant tuned to one light.";
    if (c.metric.ends_with(".shadow_error"))
      c.advice = "shadows detach (peter-panning): the bias is too large here. Scale the slope term by the texel's "
                 "size (u_texel_depth) and cap tan near grazing angles; check the culling too.";
  }
}

}  // namespace

Lab make_lab_bias_tuning() {
  Lab lab;
  lab.number = 1;
  lab.slug = "bias_tuning";
  lab.title = "Bias: acne vs peter-panning";
  lab.summary = "Write a slope-scaled bias and pick the culling so a grazing light shows neither artifact.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  auto bias = *ParamSet(renderer_param_specs()).find("shadow.bias");
  bias.default_value = 0.0005;
  auto slope = *ParamSet(renderer_param_specs()).find("shadow.slope_bias");
  slope.default_value = 2.0;
  auto elevation = *ParamSet(renderer_param_specs()).find("light.elevation");
  elevation.default_value = 10.0;
  lab.params = {bias, slope, elevation};
  lab.presets = {
      {"acne", "No bias at all: stripes of self-shadowing.", {{"shadow.bias", "0"}, {"shadow.slope_bias", "0"}}},
      {"peter-panning", "A large bias: shadows detach from their casters.", {{"shadow.bias", "0.05"}, {"shadow.slope_bias", "0"}}},
      {"tuned", "The lab's defaults.", {{"shadow.bias", "0.0005"}, {"shadow.slope_bias", "2"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    LabHooks hooks;
    hooks.includes["lab/bias.glsl"] = files.at(0).string();
    hooks.shadow_cull_override = CullDirective(files.at(0));
    return hooks;
  };
  lab.check = check_bias;
  return lab;
}

}  // namespace shadowlab
