// Lab 4: VSM's light bleeding and its fix (the course's task 5: bias and the remap of the bound).
// Demonstrates: why Chebyshev's bound lets light through stacked occluders, the remap
// [0, delta] -> 0, [delta, 1] -> [0, 1] that cuts it, the price (darker, narrower penumbrae), and a
// debug view tinting the pixels the remap changed. Check: on the stacked-occluder scene, the bleeding
// rate against the oracle with the student's delta against lab 3's unfixed test, the acne rate, and a
// sweep of delta; the default scene is measured and reported.
#include "grading/lab.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "grading/check.h"
#include "grading/probe.h"
#include "labs/vsm_features.h"
#include "core/vsm_params.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = kVsmVisibility;                      // the renderer's own VSM test
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

// The shadow test alone (grading/probe.h): one moments texel per case, read at its centre through a light
// whose texture space is world space, n.l = 1 (the bias is the constant slider). Means, variances and
// depths are chosen so float32 computes z - bias, E[z^2] - E[z]^2 and z - E[z] exactly; the reference is
// Chebyshev's bound on z - bias, remapped linearly from [delta, 1] to [0, 1] and clamped.
constexpr double kMeans[] = {0.25, 0.5, 0.75};
constexpr int kVarianceExponents[] = {-8, -11, -14, -18};
constexpr int kDistanceExponents[] = {-3, -5, -7, -9};
constexpr float kMinVariance = 0x1p-20f;
constexpr double kProbeTolerance = 1e-5;
constexpr double kMaxProbeMismatch = 0;  // cases off the reference by more than that: none
struct ProbePass {
  const char* part;  // which criterion the pass grades
  float delta, bias;
};
constexpr ProbePass kProbePasses[] = {{"remap", 0.125f, 0.0f}, {"remap", 0.3f, 0.0f}, {"bias", 0.0f, 0x1p-7f},
                                      {"combined", 0.125f, 0x1p-8f}};

double reference_visibility(double mu, double m2, double z, const ProbePass& pass) {
  const double zb = z - pass.bias;
  double p = 1.0;
  if (zb > mu) {
    const double variance = std::max(m2 - mu * mu, static_cast<double>(kMinVariance));
    p = variance / (variance + (zb - mu) * (zb - mu));
  }
  return std::clamp((p - pass.delta) / (1.0 - pass.delta), 0.0, 1.0);
}

void probe_visibility(CheckContext& ctx, CheckResult& result) {
  std::vector<glm::dvec3> cases;  // mu, m2, z
  for (double mu : kMeans)
    for (int ve : kVarianceExponents)
      for (int de : kDistanceExponents)
        for (double sign : {-1.0, 0.0, 1.0}) {
          const double z = mu + sign * std::ldexp(1.0, de) + std::ldexp(1.0, -7) * (sign > 0);  // beyond the bias too
          cases.push_back({mu, mu * mu + std::ldexp(1.0, ve), z});
        }
  constexpr int kSide = 32;
  if (cases.size() > kSide * kSide) throw std::logic_error("lab 4 probe: too many cases");
  std::vector<glm::vec2> moments;
  ProbeRequest request;
  request.fragment = "shaders/probe/visibility.frag";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    moments.push_back({static_cast<float>(cases[i].x), static_cast<float>(cases[i].y)});
    const float u = (static_cast<float>(i % kSide) + 0.5f) / kSide, v = (static_cast<float>(i / kSide) + 0.5f) / kSide;
    request.in0.push_back({u, v, static_cast<float>(cases[i].z), 1.0f});  // world = texture space; n.l = 1
    request.in1.push_back({0, 0, 1, 0});
  }
  const GlTexture map = make_probe_moments_texture(moments, kSide, kSide);
  for (const ProbePass& pass : kProbePasses)
    request.passes.push_back([&map, pass](GLuint program) {
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, map.id());
      set_uniform(program, "u_shadow_map", 0);
      set_uniform(program, "u_light_tex_matrix", glm::mat4(1.0f));
      set_uniform(program, "u_bias_constant", pass.bias);
      set_uniform(program, "u_bias_slope", 0.0f);
      set_uniform(program, "u_texel_depth", 0.0f);
      set_uniform(program, "u_min_variance", kMinVariance);
      set_uniform(program, "u_bleed_delta", pass.delta);
    });
  const auto v = run_probe(ctx.hooks(), request);
  std::map<std::string, std::pair<double, double>> wrong;  // part -> (wrong, total)
  nlohmann::json passes = nlohmann::json::array();
  for (std::size_t k = 0; k < v.size(); ++k) {
    double worst = 0.0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const double error = std::abs(v[k][i] - reference_visibility(cases[i].x, cases[i].y, cases[i].z, kProbePasses[k]));
      const bool bad = !(error <= kProbeTolerance);
      wrong[kProbePasses[k].part].first += bad;
      wrong[kProbePasses[k].part].second += 1;
      worst = std::max(worst, std::isfinite(error) ? error : 1e30);
    }
    passes.push_back({{"part", kProbePasses[k].part}, {"delta", kProbePasses[k].delta}, {"bias", kProbePasses[k].bias},
                      {"worst_error", worst}});
  }
  result.metrics["probe"] = {{"cases", cases.size()}, {"passes", passes}};
  const std::string why = "probe: exact float32 moments and depths, the CPU reference within 1e-5";
  const std::pair<const char*, const char*> parts[] = {
      {"remap", "remap the bound linearly: [0, delta] -> 0 and [delta, 1] -> [0, 1], i.e. (p - delta) / (1 - delta) "
                "clamped to [0, 1], with delta the slider u_bleed_delta."},
      {"bias", "subtract the bias from the fragment's depth before the bound: chebyshev_upper_bound(moments, z - "
               "shadow_bias(n_dot_l))."},
      {"combined", "first the bias on z, then the bound, then the remap."}};
  for (const auto& [part, advice] : parts)
    result.criteria.push_back({std::string("probe.") + part + "_mismatch", wrong[part].first / wrong[part].second,
                               Criterion::kAtMost, kMaxProbeMismatch, why, advice});
}

void check_light_bleeding(CheckContext& ctx, CheckResult& result) {
  probe_visibility(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  params.set("vsm.show_remap", 0.0);
  const Features hooks = ctx.hooks();
  Features unfixed = hooks;
  unfixed.includes["lab/visibility.glsl"] = kUnfixed;

  // 1. The default scene, reported: the fix must not hurt an ordinary scene.
  const auto d = ctx.measure(params, hooks, std::string("lab04_default_") + impl_name(ctx.impl));
  result.metrics["default_scene"] = to_json(d.metrics);

  // 2. The stacked occluders: lab 3's unfixed test, then the student's fix, at the lab's settings and
  // with the moments blurred (lab 5's 9x9 Gaussian), where bleeding spreads over many more pixels.
  ctx.use_scene(make_stacked_occluders_scene());
  const Bounds view = shadows_on_receiver(
      ctx.scene(), direction_from_angles(params.get(param::light_azimuth), params.get(param::light_elevation)));
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
                               "the fix removes at least three quarters of lab 3's bleeding"});
    result.criteria.push_back(
        {tag + ".bleeding_rate", m.metrics.bleeding_rate, Criterion::kAtMost, kMaxBleeding, "at most 1 % of the shadowed interior bleeds"});
    result.criteria.push_back({tag + ".lit_error", m.metrics.lit_error, Criterion::kAtMost, kMaxAcne,
                               "0.5 %: lit interior pixels must stay lit, and fully"});
    require_measurable(result, tag, m.metrics);
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

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "VSM: bias and light bleeding";
  lab.summary = "Cut the light that bleeds through stacked occluders: bias z, remap [0, delta] to 0.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = vsm_lab_bias_params();
  for (auto& spec :
       specs_of(param::vsm_min_variance, param::vsm_bleed_delta, param::vsm_show_remap, param::vsm_blur_radius,
                param::vsm_blur_sigma))
    lab.params.push_back(spec);
  lab.presets = {
      // On the stacked occluders the check grades, the moments blurred (radius 8, sigma 4) so that the light
      // bleeding along the low occluder's shadow edge inside the middle one's is wide enough to see.
      {"no fix", "delta = 0 and no bias: lab 3's result, blurred wide, on the stacked occluders.",
       {{"vsm.bleed_delta", "0"}, {"shadow.bias", "0"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}},
       {.provokes = "light bleeding", .fixed_by = "course"},
       {.scene = kStackedOccludersScene, .camera = kStackedOccludersCamera}},
      {"course", "delta = 0.125, as in the course, and the lab's bias.", {{"vsm.bleed_delta", "0.125"}, {"shadow.bias", "0.0005"}}},
      {"too much", "delta = 0.5, the moments blurred as in 'no fix': no bleeding, but penumbrae shrink and darken.",
       {{"vsm.bleed_delta", "0.5"}, {"vsm.blur_radius", "8"}, {"vsm.blur_sigma", "4"}},
       {.provokes = "over-darkening", .fixed_by = "course"}, {.scene = kStackedOccludersScene, .camera = kStackedOccludersCamera}},
      {"show remap", "Tint the pixels the remap changed.", {{"vsm.show_remap", "true"}}},
  };
  lab.offered_includes = {"lab/bias.glsl", "lab/chebyshev.glsl"};
  lab.make_hooks = [](const SlotFiles& files) { return vsm_features(files.at(0)); };
  lab.check = check_light_bleeding;
  // One technique per blur radius; the quick run measures 0, 2 and 4.
  for (int r : {0, 1, 2, 4, 8}) {
    const bool quick = r == 0 || r == 2 || r == 4;
    lab.bench.push_back({"vsm r" + std::to_string(r), "VSM", {{"vsm.blur_radius", std::to_string(r)}}, true, quick});
  }
  return lab;
}

}  // namespace shadowlab
