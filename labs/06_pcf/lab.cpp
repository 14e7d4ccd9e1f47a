// Lab 6: percentage-closer filtering (PCF).
// Demonstrates: averaging the depth comparison over N x N texels (3 x 3 in the lecture, up to 9 x 9),
// and the hardware comparison (sampler2DShadow, GL_COMPARE_REF_TO_TEXTURE with linear filtering: a
// bilinear 2 x 2 PCF per tap). Check: the kernel on straight edges at six orientations against a CPU
// average (probe); then, on the default scene at a 512^2 map and under held-out lights, every kernel's
// interior (beyond its reach from a true edge) within lab 1's bounds on the continuous errors.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "grading/check.h"
#include "grading/lab.h"
#include "grading/probe.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/shadow/pcf.glsl";  // the renderer's own PCF

// The kernel alone (grading/probe.h): a 64 x 64 depth map holding a straight edge (an occluder at depth 0.3
// on one side, nothing at 1.0 on the other) at several orientations, a flat receiver at depth 0.6 facing
// the light (so any bias below 0.3 gives the same comparisons), points within 6 texels of the edge away
// from texel borders. The reference averages the comparisons over the (2r+1)^2 texels around the point's
// texel, each (for a hardware tap) blended bilinearly from its 2 x 2 neighbours, clamped to the edge.
constexpr int kMapSize = 64;
constexpr float kOccluder = 0.3f, kEmpty = 1.0f, kReceiver = 0.6f, kProbeBias = 0.001f;
constexpr int kProbePoints = 600;
constexpr float kProbeReach = 6.0f;  // texels from the edge (the map's centre line) the points lie within
constexpr float kBorderMargin = 0.03f;  // of a texel: where rounding or bilinear weights may decide
constexpr double kKernelTolerance = 1e-4;
constexpr double kHardwareTolerance = 0.01;  // bilinear weights have 8 fractional bits on many GPUs
constexpr int kRadii[] = {0, 1, 2, 4};
constexpr double kMaxProbeMismatch = 0.002;

struct EdgeMap {
  float angle_deg;
  std::vector<float> depths;
  float at(int x, int y) const {
    x = std::clamp(x, 0, kMapSize - 1);
    y = std::clamp(y, 0, kMapSize - 1);
    return depths[static_cast<std::size_t>(y * kMapSize + x)];
  }
};

EdgeMap make_edge_map(float angle_deg, float offset) {
  EdgeMap m{angle_deg, std::vector<float>(kMapSize * kMapSize)};
  const float a = glm::radians(angle_deg);
  const glm::vec2 normal(-std::sin(a), std::cos(a));
  for (int y = 0; y < kMapSize; ++y)
    for (int x = 0; x < kMapSize; ++x) {
      const glm::vec2 c(x + 0.5f - kMapSize / 2.0f, y + 0.5f - kMapSize / 2.0f);
      m.depths[static_cast<std::size_t>(y * kMapSize + x)] = glm::dot(c, normal) < offset ? kOccluder : kEmpty;
    }
  return m;
}

double reference_pcf(const EdgeMap& m, glm::vec2 uv, int radius, bool hardware) {
  const float z = kReceiver - kProbeBias;
  double lit = 0.0;
  for (int ky = -radius; ky <= radius; ++ky)
    for (int kx = -radius; kx <= radius; ++kx) {
      const glm::vec2 t = (uv + glm::vec2(kx, ky) / static_cast<float>(kMapSize)) * static_cast<float>(kMapSize);
      if (!hardware) {
        lit += z > m.at(static_cast<int>(std::floor(t.x)), static_cast<int>(std::floor(t.y))) ? 0.0 : 1.0;
        continue;
      }
      const glm::vec2 b = t - 0.5f;
      const int x0 = static_cast<int>(std::floor(b.x)), y0 = static_cast<int>(std::floor(b.y));
      const double fx = b.x - x0, fy = b.y - y0;
      auto cmp = [&](int x, int y) { return z <= m.at(x, y) ? 1.0 : 0.0; };
      lit += (1 - fx) * (1 - fy) * cmp(x0, y0) + fx * (1 - fy) * cmp(x0 + 1, y0) + (1 - fx) * fy * cmp(x0, y0 + 1) +
             fx * fy * cmp(x0 + 1, y0 + 1);
    }
  return lit / ((2 * radius + 1) * (2 * radius + 1));
}

// A coordinate away from texel borders, and for hardware taps away from texel centres too (where the
// bilinear footprint switches neighbours).
float away_from_borders(float texels, std::mt19937& rng) {
  std::uniform_real_distribution<float> u(kBorderMargin, 0.5f - kBorderMargin);
  const float inside = u(rng) + (std::uniform_int_distribution<int>(0, 1)(rng) ? 0.5f : 0.0f);
  return (std::floor(texels) + inside) / kMapSize;
}

void probe_kernel(CheckContext& ctx, CheckResult& result) {
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Orientations: along both axes, both diagonals and two drawn from the seed.
  std::vector<EdgeMap> maps;
  for (float angle : {0.0f, 90.0f, 45.0f, 135.0f, 180.0f * unit(rng), 180.0f * unit(rng)})
    maps.push_back(make_edge_map(angle, unit(rng) - 0.5f));
  ProbeRequest request;
  request.fragment = "shaders/probe/visibility.frag";
  std::vector<glm::vec2> points;
  for (int i = 0; i < kProbePoints; ++i) {
    // Within kProbeReach texels of the map's centre line (the edge passes through the centre).
    const glm::vec2 t(kMapSize / 2.0f + 2.0f * kProbeReach * (unit(rng) - 0.5f),
                      kMapSize / 2.0f + 2.0f * kProbeReach * (unit(rng) - 0.5f));
    const glm::vec2 uv(away_from_borders(t.x, rng), away_from_borders(t.y, rng));
    points.push_back(uv);
    request.in0.push_back({uv.x, uv.y, kReceiver, 1.0f});  // world = texture space; n.l = 1
    request.in1.push_back({0, 0, 1, 0});
  }
  std::vector<GlTexture> textures;
  for (const auto& m : maps) textures.push_back(make_probe_depth_texture(m.depths, kMapSize));
  const GlSampler compare = make_compare_sampler();
  struct Pass {
    std::size_t map;
    int radius;
    bool hardware;
  };
  std::vector<Pass> passes;
  for (std::size_t k = 0; k < maps.size(); ++k)
    for (int radius : kRadii)
      for (bool hardware : {false, true}) {
        passes.push_back({k, radius, hardware});
        request.passes.push_back([&, k, radius, hardware](GLuint program) {
          bind_probe_shadow_map(program, textures[k], compare);
          set_uniform(program, "u_light_tex_matrix", glm::mat4(1.0f));
          set_uniform(program, "u_bias_constant", kProbeBias);
          set_uniform(program, "u_bias_slope", 0.0f);
          set_uniform(program, "u_texel_depth", 0.0f);
          set_uniform(program, "u_pcf_radius", radius);
          set_uniform(program, "u_pcf_hardware", hardware ? 1 : 0);
        });
      }
  const auto v = run_probe(ctx.hooks(), request);
  double wrong[2] = {0, 0}, total[2] = {0, 0};
  nlohmann::json per_pass = nlohmann::json::array();
  for (std::size_t p = 0; p < passes.size(); ++p) {
    const Pass& pass = passes[p];
    double pass_wrong = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double error = std::abs(v[p][i] - reference_pcf(maps[pass.map], points[i], pass.radius, pass.hardware));
      const bool bad = !(error <= (pass.hardware ? kHardwareTolerance : kKernelTolerance));
      pass_wrong += bad;
    }
    wrong[pass.hardware] += pass_wrong;
    total[pass.hardware] += static_cast<double>(points.size());
    per_pass.push_back({{"edge_angle_deg", maps[pass.map].angle_deg}, {"kernel", 2 * pass.radius + 1},
                        {"hardware", pass.hardware}, {"mismatch", pass_wrong / static_cast<double>(points.size())}});
  }
  result.metrics["probe"] = {{"map_size", kMapSize}, {"points", points.size()}, {"passes", per_pass}};
  const std::string why = "probe: straight edges at 6 orientations, kernels 1-9, against the CPU average";
  result.criteria.push_back(
      {"probe.kernel_mismatch", wrong[0] / total[0], Criterion::kAtMost, kMaxProbeMismatch, why,
       "average the comparison over all (2r+1) x (2r+1) texels around the point, in both directions, one texel "
       "(1 / textureSize) apart, centred on the point's own texel."});
  result.criteria.push_back(
      {"probe.hardware_mismatch", wrong[1] / total[1], Criterion::kAtMost, kMaxProbeMismatch, why,
       "with u_pcf_hardware, take the same (2r+1)^2 taps through u_shadow_map_compare: texture(u_shadow_map_compare, "
       "vec3(uv, depth)) returns each tap's bilinear 2 x 2 comparison."});
}

// The images: every kernel on the lab's scene, two of them under held-out lights. A pixel nearer a true
// shadow edge than the kernel reaches (the corner tap is r sqrt 2 texels away, plus the texel the pixel
// falls in, plus one for a hardware tap's 2 x 2 footprint) is legitimately partly lit: the band grows with
// the kernel, so the interior must come out exactly 0 or 1 for every kernel.
BandSpec kernel_band(int radius, bool hardware) {
  BandSpec band = grading_band();
  band.radius_texels = static_cast<float>(radius) * std::numbers::sqrt2_v<float> + 1.5f + (hardware ? 1.0f : 0.0f);
  band.samples = std::max(8, static_cast<int>(std::ceil(2.0f * std::numbers::pi_v<float> * band.radius_texels / 1.5f)));
  return band;
}

struct KernelCase {
  const char* kernel;
  bool hardware;
};
constexpr KernelCase kCases[] = {{"1", false}, {"3", false}, {"5", false}, {"7", false}, {"9", false},
                                 {"1", true},  {"3", true}};
constexpr KernelCase kHeldOutKernels[] = {{"5", false}, {"9", false}, {"3", true}};
const std::vector<HeldOutRange> kHeldOut = {{20.0f, 45.0f, {"512", "1024"}, {"default", "stacked"}},
                                            {45.0f, 80.0f, {"512", "1024"}, {"default", "stacked"}}};
const HardLimits kLimits{
    .why = "lab 1's bounds, interior beyond the kernel's reach",
    .lit_advice = "acne inside lit areas: a tap k texels away reads the receiver k texels along its slope, so the bias "
                  "must grow with the kernel's reach (lab 1's bias times 1 + r sqrt(2): the corner taps' distance).",
    .shadow_advice = "light inside shadows: average the comparisons (0 or 1 each), not the depths, and keep the bias small."};
// Images are graded at this size: the band's many samples per pixel make the oracle dearer.
constexpr int kWidth = 640, kHeight = 360;

void measure_kernel(CheckContext& ctx, CheckResult& result, const ParamSet& params, const KernelCase& c,
                    const std::string& prefix, nlohmann::json& kernels) {
  ParamSet p = params;
  p.set_from_string("pcf.kernel", c.kernel);
  p.set("pcf.hardware", c.hardware ? 1.0 : 0.0);
  const std::string tag = prefix + "k" + c.kernel + (c.hardware ? "hw" : "");
  const int radius = (c.kernel[0] - '0') / 2;
  const auto m = ctx.measure(p, ctx.hooks(), "lab06_" + tag + "_" + impl_name(ctx.impl), nullptr,
                             kernel_band(radius, c.hardware), kWidth, kHeight);
  grade_hard_shadow(result, tag, m.metrics, kLimits);
  std::size_t band = 0, soft = 0;  // reported: how much of the band the filter softened
  for (std::size_t i = 0; i < m.visibility.size(); ++i) {
    if (!m.truth.valid[i] || m.truth.interior[i]) continue;
    ++band;
    soft += m.visibility[i] > 0.02f && m.visibility[i] < 0.98f;
  }
  kernels.push_back({{"case", tag}, {"kernel", c.kernel}, {"hardware", c.hardware}, {"metrics", to_json(m.metrics)},
                     {"soft_edge_share", band ? static_cast<double>(soft) / static_cast<double>(band) : 0.0}});
}

void check_pcf(CheckContext& ctx, CheckResult& result) {
  probe_kernel(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  nlohmann::json kernels = nlohmann::json::array();
  const auto out_dir = ctx.out_dir;
  for (const auto& c : kCases) {
    const std::string tag = std::string("k") + c.kernel + (c.hardware ? "hw" : "");
    ctx.out_dir = tag == "k1" || tag == "k5" || tag == "k3hw" ? out_dir : std::filesystem::path{};
    measure_kernel(ctx, result, params, c, "", kernels);
  }
  ctx.out_dir = out_dir;
  const auto held_out = draw_directional_cases(ctx, kHeldOut);
  for (std::size_t i = 0; i < held_out.size(); ++i) {
    measure_kernel(ctx, result, held_out[i].apply(ctx, params), kHeldOutKernels[i % std::size(kHeldOutKernels)],
                   held_out[i].tag + ".", kernels);
    result.conditions.push_back(held_out[i].to_json());
  }
  ctx.use_default_scene();
  result.metrics["kernels"] = kernels;
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Percentage-closer filtering";
  lab.summary = "Average the shadow test over N x N texels, in a loop or with the hardware's sampler2DShadow.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSpec bias = param::shadow_bias.spec(), slope = param::shadow_slope_bias.spec();
  ParamSpec size = param::shadow_map_size.spec();
  bias.default_value = 0.0005;  // lab 1's solution
  slope.default_value = 2.0;
  size.default_value = 1.0;  // 512^2: texels several pixels wide on screen, where filtering shows
  lab.params = {bias, slope, size};
  for (const auto& spec : find_shadow_test("pcf").params) lab.params.push_back(spec);
  lab.presets = {
      {"single tap", "1 x 1: the hard, jagged edge of lab 0.", {{"pcf.kernel", "1"}, {"pcf.hardware", "false"}},
       {.provokes = "aliasing", .fixed_by = "lecture"}, {.camera = kShadowEdgeCamera}},
      {"lecture", "3 x 3, as in the lecture.", {{"pcf.kernel", "3"}, {"pcf.hardware", "false"}}},
      {"wide", "9 x 9: wide soft edges, 81 taps per pixel.", {{"pcf.kernel", "9"}, {"pcf.hardware", "false"}}},
      {"hardware 2x2", "One sampler2DShadow tap: bilinear 2 x 2 PCF for free.", {{"pcf.kernel", "1"}, {"pcf.hardware", "true"}}},
      {"matched to the sun",
       "A 3-degree sun, the kernel as wide as its penumbra 1 unit under a blocker: right there only (Penumbra error).",
       {{"light.size", "3"}, {"pcf.match_light", "true"}, {"pcf.match_distance", "1"}, {"pcf.hardware", "false"}}},
  };
  lab.offered_includes = {"lab/bias.glsl"};
  // The exercise (or the solution) in the visibility slot, with PCF's uniforms (renderer/shadow_tests/pcf.cpp).
  lab.make_hooks = [hooks = visibility_lab_hooks()](const SlotFiles& files) {
    Features features = hooks(files);
    features.shadow_test = "pcf";
    return features;
  };
  lab.check = check_pcf;
  for (const auto& spec : lab.params)  // one technique per kernel size
    if (spec.key == "pcf.kernel")
      for (const auto& choice : spec.choices) lab.bench.push_back({"pcf " + choice, "PCF", {{"pcf.kernel", choice}}});
  // Against a sun with a size: the kernel matched to it (a single tap at size 0).
  lab.bench.push_back({"pcf matched", "PCF", {{"pcf.kernel", "1"}, {"pcf.match_light", "true"}}});
  return lab;
}

}  // namespace shadowlab
