// Lab 6: percentage-closer filtering (PCF).
// Demonstrates: averaging the depth comparison over N x N texels (3 x 3 in the lecture, up to 9 x 9),
// and the hardware comparison (sampler2DShadow, GL_COMPARE_REF_TO_TEXTURE with linear filtering: a
// bilinear 2 x 2 PCF per tap). Check: on the default scene at a 512^2 map (where texels are large on
// screen), every kernel keeps interior acne and leak within lab 1's bounds, and the wider kernels'
// edge-band error is compared with a single tap's; the figures per kernel are printed.
#include <cstdio>

#include "labs/check.h"
#include "labs/lab.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = "labs/06_pcf/exercise.glsl";
constexpr const char* kSolution = "shaders/shadow/pcf.glsl";  // the renderer's own PCF

// Lab 1's bounds over interior pixels.
constexpr double kMaxAcne = 0.001;
constexpr double kMaxLeak = 0.005;

struct KernelCase {
  const char* kernel;
  bool hardware;
};

// A pixel counts as filtered ("soft") when its visibility is strictly between these: neither a single
// tap's 0 or 1 nor float noise around them.
constexpr double kSoftLow = 0.02, kSoftHigh = 0.98;
// The least share of edge-band pixels a filter must leave soft: half of what the solution measured at
// the lab's defaults (README: 3x3 0.516, 5x5 0.794, 7x7 0.799, 9x9 0.801, hardware 1x1 0.234, hardware
// 3x3 0.660), so a correct PCF passes with a factor 2 to spare and a single tap (0 everywhere) cannot.
double min_soft_share(const KernelCase& c) {
  const int n = c.kernel[0] - '0';
  if (c.hardware) return n == 1 ? 0.12 : 0.33;
  return n == 3 ? 0.25 : 0.40;
}
constexpr KernelCase kCases[] = {{"1", false}, {"3", false}, {"5", false}, {"7", false}, {"9", false},
                                 {"1", true},  {"3", true}};

void check_pcf(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const LabHooks hooks = ctx.hooks();
  nlohmann::json kernels = nlohmann::json::array();
  std::printf("    PCF by kernel (%s, map %s):\n", impl_name(ctx.impl), params.get_choice("shadow.map_size").c_str());
  std::printf("      kernel  hw  acne      leak      mae_edge  mae_interior\n");
  const auto out_dir = ctx.out_dir;
  double single_tap_edge = 0.0;
  for (const auto& c : kCases) {
    ParamSet p = params;
    p.set_from_string("pcf.kernel", c.kernel);
    p.set("pcf.hardware", c.hardware ? 1.0 : 0.0);
    const std::string tag = std::string("k") + c.kernel + (c.hardware ? "hw" : "");
    ctx.out_dir = tag == "k1" || tag == "k5" || tag == "k3hw" ? out_dir : std::filesystem::path{};
    const auto m = ctx.measure(p, hooks, "lab06_" + tag + "_" + impl_name(ctx.impl));
    std::printf("      %sx%s  %s   %.5f   %.5f   %.5f   %.6f\n", c.kernel, c.kernel, c.hardware ? "y" : "n",
                m.metrics.acne_rate, m.metrics.leak_rate, m.metrics.mae_edge, m.metrics.mae_interior);
    kernels.push_back({{"kernel", c.kernel}, {"hardware", c.hardware}, {"metrics", to_json(m.metrics)}});
    result.criteria.push_back({tag + ".acne_rate", m.metrics.acne_rate, Criterion::kAtMost, kMaxAcne, "lab 1's bound"});
    result.criteria.push_back({tag + ".leak_rate", m.metrics.leak_rate, Criterion::kAtMost, kMaxLeak, "lab 1's bound"});
    // The share of edge-band pixels the filter left between lit and shadowed: 0 for a single tap.
    std::size_t band = 0, soft = 0;
    for (std::size_t i = 0; i < m.visibility.size(); ++i) {
      if (!m.truth.valid[i] || m.truth.interior[i]) continue;
      ++band;
      if (m.visibility[i] > kSoftLow && m.visibility[i] < kSoftHigh) ++soft;
    }
    const double soft_share = band ? static_cast<double>(soft) / static_cast<double>(band) : 0.0;
    kernels.back()["soft_edge_share"] = soft_share;
    kernels.back()["mae_edge_over_single_tap"] = single_tap_edge > 0 ? m.metrics.mae_edge / single_tap_edge : 0.0;
    std::printf("        soft share of the edge band %.4f\n", soft_share);
    if (tag == "k1") single_tap_edge = m.metrics.mae_edge;
    if (tag != "k1")
      result.criteria.push_back({tag + ".soft_edge_share", soft_share, Criterion::kAtLeast, min_soft_share(c),
                                 "filtered edges: half the solution's measured share"});
  }
  ctx.out_dir = out_dir;
  result.metrics["kernels"] = kernels;
}

}  // namespace

Lab make_lab_pcf() {
  Lab lab;
  lab.number = 6;
  lab.slug = "pcf";
  lab.title = "Percentage-closer filtering";
  lab.summary = "Average the shadow test over N x N texels, in a loop or with the hardware's sampler2DShadow.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSet base(renderer_param_specs());
  ParamSpec bias = *base.find("shadow.bias"), slope = *base.find("shadow.slope_bias"), size = *base.find("shadow.map_size");
  bias.default_value = 0.0005;  // lab 1's solution
  slope.default_value = 2.0;
  size.default_value = 1.0;  // 512^2: texels several pixels wide on screen, where filtering shows
  lab.params = {bias, slope, size};
  for (auto& spec : technique_param_specs({"pcf.kernel", "pcf.hardware"})) lab.params.push_back(spec);
  lab.presets = {
      {"single tap", "1 x 1: the hard, jagged edge of lab 0.", {{"pcf.kernel", "1"}, {"pcf.hardware", "false"}}},
      {"lecture", "3 x 3, as in the lecture.", {{"pcf.kernel", "3"}, {"pcf.hardware", "false"}}},
      {"wide", "9 x 9: wide soft edges, 81 taps per pixel.", {{"pcf.kernel", "9"}, {"pcf.hardware", "false"}}},
      {"hardware 2x2", "One sampler2DShadow tap: bilinear 2 x 2 PCF for free.", {{"pcf.kernel", "1"}, {"pcf.hardware", "true"}}},
  };
  lab.offered_includes = {"lab/bias.glsl"};
  lab.make_hooks = visibility_lab_hooks();
  lab.check = check_pcf;
  return lab;
}

}  // namespace shadowlab
