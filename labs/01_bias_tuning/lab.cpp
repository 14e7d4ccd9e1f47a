// Lab 1: bias tuning, acne against peter-panning.
// Demonstrates: why a constant bias fails at grazing light, a slope-scaled bias in texels, and culling
// front faces in the shadow pass. Check: the default scene under a grazing light (elevation 10 deg).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "grading/check.h"
#include "grading/lab.h"
#include "grading/probe.h"

namespace shadowlab {

namespace {

// Lab 1's shadow.cull: the renderer's three choices and a fourth, the lab's default, that leaves the
// culling to the file's `#define SHADOW_PASS_CULL` line (what the check grades). The other three try a
// culling without editing the file (the presets "cull front" and "cull back").
constexpr double kCullFromFile = 3.0;

// The culling the student chose with `#define SHADOW_PASS_CULL ...` in the exercise file: 0 none,
// 1 front, 2 back (the order of the shadow.cull parameter's choices), unless shadow.cull names one of
// these. Re-read when the file changes; called every frame, so an unchanged file costs one stat and no
// allocation (the path is resolved once).
class CullDirective {
 public:
  explicit CullDirective(std::filesystem::path file) : file_(std::move(file)) {}
  int operator()(const ParamSet& params) {
    // A parameter set without lab 1's declaration of shadow.cull (a benchmark's, a test's) leaves it to the file.
    const double chosen = params.get("shadow.cull");
    if (chosen != kCullFromFile && params.find("shadow.cull")->choices.size() > kCullFromFile) return static_cast<int>(chosen);
    if (!resolved_) {
      file_ = data_dir() / file_;
      resolved_ = true;
    }
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(file_, ec);
    if (ec || time == seen_) return cull_;
    seen_ = time;
    std::ifstream in(file_);
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
  bool resolved_ = false;
  std::filesystem::file_time_type seen_{};
  int cull_ = 0;
};

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = SHADOWLAB_LAB_FOLDER "/solution.glsl";

// A constant that works at one light and one map size fails at another: the held-out cases span low
// and high lights (the depth change across one texel grows with tan(angle of incidence)) and coarse and
// fine maps (a texel's size), on both built-in scenes. The lowest light stays above 6 degrees: below
// 5.7 the ground itself is lit beyond 84 degrees of incidence, which no check grades (grading_band());
// below 15 degrees the stacked scene's shadows leave its receiver, so only the default scene is used.
const std::vector<HeldOutRange> kHeldOut = {{6.0f, 9.0f, {"256", "512"}, {"default"}},
                                            {9.0f, 20.0f, {"256", "512", "1024", "2048"}, {"default"}},
                                            {20.0f, 45.0f, {"256", "512", "1024", "2048"}, {"stacked", "default"}},
                                            {45.0f, 89.0f, {"256", "512", "1024", "2048"}, {"stacked", "default"}}};

// The bias function on its own (grading/probe.h): shadow_bias at these cosines, under four settings of
// the sliders, against what the lab asks of it.
constexpr float kCosines[] = {1.0f, 0.9f, 0.7f, 0.5f, 0.3f, 0.2f, 0.1f, 0.05f, 0.01f, 0.001f};
constexpr std::size_t kAtOne = 0, kAtSteep = 5, kAtGrazing = 9;  // indices: n.l = 1, 0.2, 0.001
struct Sliders {
  float constant, slope, texel_depth;
};
constexpr Sliders kBase{5e-4f, 2.0f, 1e-3f};
constexpr Sliders kSettings[] = {kBase, {2e-3f, 2.0f, 1e-3f}, {5e-4f, 4.0f, 1e-3f}, {5e-4f, 2.0f, 2e-3f}};
// Values that are not finite or negative, and steps where the bias shrinks as the light grazes: none.
constexpr double kMaxBadBiasValues = 0;
// How the growth from n.l = 1 to n.l = 0.2 (tan = 4.9, sec = 5) may deviate from doubling when the
// slope or the texel doubles, and how far the constant's effect may be from the slider's change.
constexpr double kProportionTolerance = 0.2;
constexpr double kConstantTolerance = 0.1;
// The bias at n.l = 0.001 may exceed the bias at n.l = 1 by at most this many (slope x texel): tan
// capped near 84 degrees is 9.5-10, 1 / n.l capped at 10 is 10.
constexpr double kMaxGrazingGrowth = 12.0;
constexpr double kMinSteepGrowth = 2.0;  // at n.l = 0.2 tan is 4.9: at least 2 (slope x texel) more than at 1

void probe_bias_function(CheckContext& ctx, CheckResult& result) {
  ProbeRequest request;
  request.fragment = "shaders/probe/bias.frag";
  for (float c : kCosines) request.in0.push_back({c, 0, 0, 0});
  for (const Sliders& s : kSettings)
    request.passes.push_back([s](GLuint program) {
      set_uniform(program, "u_bias_constant", s.constant);
      set_uniform(program, "u_bias_slope", s.slope);
      set_uniform(program, "u_texel_depth", s.texel_depth);
    });
  const auto v = run_probe(ctx.hooks(), request);
  double bad = 0, not_monotonic = 0;
  for (const auto& pass : v) {
    for (std::size_t i = 0; i < pass.size(); ++i) {
      if (!std::isfinite(pass[i]) || pass[i] < 0.0f) ++bad;
      if (i > 0 && pass[i] < pass[i - 1] - 1e-7f) ++not_monotonic;
    }
  }
  const double unit = static_cast<double>(kBase.slope) * kBase.texel_depth;  // one (slope x texel)
  auto growth = [&](std::size_t pass) { return static_cast<double>(v[pass][kAtSteep]) - v[pass][kAtOne]; };
  const double steep = growth(0) / unit;
  const double constant_effect = (static_cast<double>(v[1][kAtOne]) - v[0][kAtOne]) / (kSettings[1].constant - kBase.constant);
  const double slope_ratio = growth(0) != 0.0 ? growth(2) / growth(0) : 0.0;
  const double texel_ratio = growth(0) != 0.0 ? growth(3) / growth(0) : 0.0;
  const double grazing = (static_cast<double>(v[0][kAtGrazing]) - v[0][kAtOne]) / unit;
  result.metrics["bias_function"] = {{"cosines", kCosines}, {"base", v[0]}, {"constant_2e-3", v[1]}, {"slope_4", v[2]},
                                     {"texel_depth_2e-3", v[3]}};
  const std::string why = "shadow_bias() probed at n.l from 1 to 0.001 with the sliders varied";
  result.criteria.push_back({"bias.non_finite_or_negative", bad, Criterion::kAtMost, kMaxBadBiasValues, why,
                             "the bias must be a finite, non-negative depth at every n.l in (0, 1]."});
  result.criteria.push_back({"bias.decreasing_with_slope", not_monotonic, Criterion::kAtMost, kMaxBadBiasValues, why,
                             "the bias must never shrink as the light gets more grazing (n.l smaller)."});
  result.criteria.push_back({"bias.growth_at_steep_slope", steep, Criterion::kAtLeast, kMinSteepGrowth, why,
                             "from n.l = 1 to n.l = 0.2 the bias must grow by about tan(a) = 4.9 times "
                             "u_bias_slope * u_texel_depth: make it grow with the slope, in texels."});
  result.criteria.push_back({"bias.constant_slider_error", std::abs(constant_effect - 1.0), Criterion::kAtMost,
                             kConstantTolerance, why, "keep u_bias_constant (the slider Constant bias) as the bias's constant part."});
  result.criteria.push_back({"bias.slope_slider_error", std::abs(slope_ratio - 2.0), Criterion::kAtMost,
                             kProportionTolerance, why, "the slope term must be proportional to u_bias_slope (the slider)."});
  result.criteria.push_back({"bias.texel_size_error", std::abs(texel_ratio - 2.0), Criterion::kAtMost, kProportionTolerance,
                             why, "the slope term must be proportional to u_texel_depth (one texel's size in depth units)."});
  result.criteria.push_back({"bias.growth_at_grazing", grazing, Criterion::kAtMost, kMaxGrazingGrowth, why,
                             "cap tan(a) near 84 degrees (about 10): unbounded, the bias lifts whole shadows off "
                             "surfaces the light grazes."});
}

const HardLimits kLimits{
    .lit_advice = "acne: the bias is too small for this light or map size. Make it grow with the slope (tan of the angle "
                  "of incidence) and with the texel's size (u_texel_depth), not a constant tuned to one light.",
    .shadow_advice = "shadows detach (peter-panning): the bias is too large here. Scale the slope term by the texel's "
                     "size (u_texel_depth) and cap tan near grazing angles; check the culling too."};

// The culling on its own (task 2): one picture drawn with the graded file's `#define SHADOW_PASS_CULL`
// and the reference solution's bias, so that its criteria (`culling.*`) name the culling whatever bias
// the student wrote. A low light on a coarse map, where culling front faces leaks most on this scene
// (the single-sided ground is culled and the boxes' feet peter-pan: INSTRUCTOR.md has the figures).
constexpr double kCullingElevation = 8.0;
constexpr int kCullingMapSize = 256;
const HardLimits kCullingLimits{
    .why = "lab 1's bounds (0.1 % acne, 0.5 % leak, interior pixels), drawn with your culling and the reference bias",
    .lit_advice = "acne with your culling and a correct bias: the map stores the faces the light sees, culled wrongly.",
    .shadow_advice = "shadows leak with your culling even with a correct bias: culling FRONT faces stores the boxes' far "
                     "sides and drops the single-sided ground, so the ground behind the boxes' feet is lit. Use NONE "
                     "or BACK on this scene."};

// The "cull front" preset's view: low beside the big box's shadow-side corner, where its far sides meet
// the ground. Against "no culling" 33.43 % of a 1280x720 frame's pixels differ (cli.preset_contrast): the
// ground behind both feet is lit in a wedge nearly as wide as the box.
constexpr const char* kCullLeakCamera = "eye=-4.6,0.8,0.6 target=-3.4,0.2,-0.6 fov=40";

void check_culling(CheckContext& ctx, CheckResult& result, ParamSet params) {
  Features hooks = ctx.lab.hooks(Impl::Solution);
  hooks.shadow_cull_override = ctx.hooks().shadow_cull_override;
  params.set("light.elevation", kCullingElevation);
  params.set_from_string("shadow.map_size", std::to_string(kCullingMapSize));
  const auto m = ctx.measure(params, hooks, std::string("lab01_culling_") + impl_name(ctx.impl));
  grade_hard_shadow(result, "culling", m.metrics, kCullingLimits);
}

void check_bias(CheckContext& ctx, CheckResult& result) {
  // 1. The function alone.
  probe_bias_function(ctx, result);
  // 2. Images: the lab's grazing light, then held-out lights, map sizes and scenes.
  ParamSet params = ctx.params();
  params.set("light.elevation", 10.0);  // grazing light: where a constant bias breaks down
  params.set("view.debug_quad", 0.0);
  params.set("shadow.cull", kCullFromFile);  // the file's #define line is graded, whatever the parameter says
  grade_lab_and_held_out_lights(ctx, result, "lab01", "grazing", params, params, kHeldOut, kLimits);
  // 3. The culling alone.
  check_culling(ctx, result, params);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Bias: acne vs peter-panning";
  lab.summary = "Write a slope-scaled bias and pick the culling so a grazing light shows neither artifact.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSpec bias = param::shadow_bias.spec();
  bias.default_value = 0.0005;
  ParamSpec slope = param::shadow_slope_bias.spec();
  slope.default_value = 2.0;
  ParamSpec elevation = param::light_elevation.spec();
  elevation.default_value = 10.0;
  auto cull = *ParamSet(renderer_param_specs()).find("shadow.cull");
  cull.choices.push_back("#define");
  cull.max = cull.default_value = kCullFromFile;
  cull.tooltip = "Which faces the shadow pass skips. #define: as the file's `#define SHADOW_PASS_CULL` line says (what "
                 "the check grades); none, front or back: try one without editing the file.";
  lab.params = {bias, slope, elevation, cull};
  lab.presets = {
      {"acne", "No bias at all: stripes of self-shadowing.", {{"shadow.bias", "0"}, {"shadow.slope_bias", "0"}},
       {.provokes = "acne", .fixed_by = "tuned"}},
      {"peter-panning", "A large bias under a low light, seen from the thin plate's foot: its shadow detaches from it.",
       {{"shadow.bias", "0.05"}, {"shadow.slope_bias", "0"}, {"light.elevation", "20"}},
       {.provokes = "peter-panning", .fixed_by = "tuned"}, {.camera = "eye=-1.6,0.7,2.6 target=0.1,0.1,0.4 fov=40"}},
      {"tuned", "The lab's defaults.", {{"shadow.bias", "0.0005"}, {"shadow.slope_bias", "2"}, {"shadow.cull", "#define"}}},
      {"cull front", "Front faces culled in the shadow pass: the map holds no ground, only the boxes' far sides; light leaks in at their feet.",
       {{"shadow.cull", "front"}, {"light.elevation", "8"}, {"shadow.map_size", "256"}},
       {.provokes = "culling leak", .fixed_by = "no culling"}, {.camera = kCullLeakCamera}},
      {"no culling", "Nothing culled in the shadow pass (the solution's #define): the bias alone keeps lit faces lit.",
       {{"shadow.cull", "none"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.includes["lab/bias.glsl"] = files.at(0).string();
    hooks.shadow_cull_override = CullDirective(files.at(0));
    return hooks;
  };
  lab.check = check_bias;
  lab.bench = {{"hard", "hard", {}}};
  return lab;
}

}  // namespace shadowlab
