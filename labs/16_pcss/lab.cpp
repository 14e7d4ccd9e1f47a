// Lab 16: percentage-closer soft shadows (PCSS) under a sun with a size.
// Demonstrates: a light with a size casts an umbra (sees none of the light) and a penumbra (sees part of
// it); the penumbra widens with the light's size and the blocker-receiver distance and shrinks to a hard
// shadow as either goes to 0. PCSS (shaders/shadow/pcss.glsl) searches the map for blockers, takes their
// mean distance, estimates the penumbra's width and filters (variable-width PCF) over it. The student
// writes the estimate, penumbra_width (lab/penumbra.glsl).
// Check: the function on its own against the CPU formula over many (receiver, blocker, size) triples (a
// probe); PCSS with it on the lab's scene and under held-out suns (direction, size, map size, scene drawn
// from the seed), graded against the soft truth (the visible fraction of the sun's disk per pixel); and
// with light.size 0, where it must be the hard shadow of lab 0.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "grading/check.h"
#include "grading/lab.h"
#include "grading/probe.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/shadow/penumbra.glsl";

// The probe: receivers from kMinReceiver to kMaxReceiver world units behind the map's near plane, blockers
// anywhere between the plane and the receiver (every 16th touching it), suns up to the slider's 10 degrees
// (every 16th of size 0). A case is wrong when the width is off by more than kProbeRelative of the
// formula's (2 tan(a / 2), tan a and a itself, all right to first order, differ by at most 0.8 % at
// 10 degrees) plus kProbeAbsolute world units (float rounding).
constexpr int kProbeCases = 512;
constexpr float kMinReceiver = 0.5f, kMaxReceiver = 30.0f, kMaxSunDegrees = 10.0f;
constexpr double kProbeRelative = 0.02;
constexpr double kProbeAbsolute = 1e-4;
constexpr double kMaxProbeMismatch = 0.002;

// The images: the lab's sun and the held-out ones, at this size (the soft truth's samples per penumbra
// pixel make the oracle dearer).
constexpr int kWidth = 640, kHeight = 360;
constexpr float kSunDegrees = 4.0f;  // the lab's own sun (light.size's default here)
constexpr float kHeldOutMinDegrees = 2.0f, kHeldOutMaxDegrees = 8.0f;
// PCSS against the soft truth: mean |visibility - visible fraction| over the penumbra. Measured with the
// solution over seeds 1-30 (the lab's sun and 60 held-out suns): 0.0417 at the lab's sun, held out
// 0.012-0.062 (worst: seed 10, a 2-degree sun on a 1024^2 map, where the penumbra is a few texels wide).
// The project's kPenumbraErrorLimit (0.05) is not reachable by a right PCSS here: it failed 8 of the 60
// held-out suns. PCSS's own errors, seen in the diff pictures: at contact (next to a box's base the
// blocker search averages the box's top with its foot, so the penumbra is estimated too wide and too
// dark) and on the sphere's terminator (no plane there). Wrong estimates at seed 1 (the lab's sun / the
// two held-out ones): a hard shadow 0.176 / 0.202 / 0.204, half the width 0.097 / 0.101 / 0.104, a
// constant width tuned to this scene 0.068 / 0.091 / 0.068, the others 0.14-0.27. The limit sits above
// the solution's worst with a fifth to spare and below every formula mistake but the tuned constant
// (which the probe fails).
constexpr double kPenumbraLimit = 0.08;
// The umbra (fully shadowed interior): the same contact error leaks light into it. Measured with the
// solution over seeds 1-30: at most 0.0077 (seed 16), above lab 1's 0.005; the lit region at most 0.00054.
constexpr double kUmbraLeakLimit = 0.012;

double reference_width(double receiver, double blocker, double degrees) {
  return (receiver - blocker) * 2.0 * std::tan(degrees * std::numbers::pi / 180.0 * 0.5);
}

void probe_penumbra(CheckContext& ctx, CheckResult& result) {
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  ProbeRequest request;
  request.fragment = "shaders/probe/penumbra.frag";
  for (int i = 0; i < kProbeCases; ++i) {
    const float receiver = kMinReceiver + (kMaxReceiver - kMinReceiver) * unit(rng);
    const float blocker = i % 16 == 5 ? receiver : receiver * unit(rng);
    const float size = i % 16 == 11 ? 0.0f : kMaxSunDegrees * unit(rng);
    request.in0.push_back({receiver, blocker, size, 0.0f});
  }
  const auto v = run_probe(ctx.hooks(), request);
  int wrong = 0, first_wrong = -1;
  double worst = 0.0;
  for (int i = 0; i < kProbeCases; ++i) {
    const glm::vec4& in = request.in0[static_cast<std::size_t>(i)];
    const double want = reference_width(in.x, in.y, in.z);
    const double got = v[0][static_cast<std::size_t>(i)];
    const double error = std::abs(got - want);
    const bool bad = !(error <= kProbeRelative * std::abs(want) + kProbeAbsolute);  // NaN is wrong
    wrong += bad;
    if (bad && first_wrong < 0) first_wrong = i;
    if (std::isfinite(error)) worst = std::max(worst, error);
  }
  nlohmann::json probe = {{"cases", kProbeCases}, {"wrong", wrong}, {"worst_error_world", worst}};
  std::string advice =
      "the penumbra is where the point sees part of the sun's disk: its width grows with the sun's angular size "
      "and with the distance from the blocker to the receiver, is 0 when either is 0, and light_size is in degrees.";
  if (first_wrong >= 0) {
    const glm::vec4& in = request.in0[static_cast<std::size_t>(first_wrong)];
    const double got = v[0][static_cast<std::size_t>(first_wrong)];
    const double want = reference_width(in.x, in.y, in.z);
    probe["example"] = {{"receiver_depth", in.x}, {"blocker_depth", in.y}, {"light_size", in.z}, {"returned", got},
                        {"expected", want}};
    char s[256];
    std::snprintf(s, sizeof s, " For example receiver_depth %.3g, blocker_depth %.3g, light_size %.3g deg: "
                  "returned %.4g, expected %.4g.", in.x, in.y, in.z, got, want);
    advice += s;
  }
  result.metrics["probe"] = probe;
  result.criteria.push_back({"probe.penumbra_mismatch", static_cast<double>(wrong) / kProbeCases, Criterion::kAtMost,
                             kMaxProbeMismatch,
                             "probe: penumbra_width on 512 (receiver, blocker, size) triples against the CPU formula, "
                             "within 2 % (+1e-4)",
                             advice});
}

const std::vector<HeldOutRange> kHeldOut = {{25.0f, 45.0f, {"1024", "2048"}, {"default", "stacked"}},
                                            {45.0f, 75.0f, {"1024", "2048"}, {"default", "stacked"}}};

HardLimits pcss_limits() {
  HardLimits limits;
  limits.why = "lab 1's acne bound over the fully lit region; PCSS's measured leak at contact in the umbra";
  limits.shadow_error = kUmbraLeakLimit;
  limits.lit_advice = "the fully lit region is darkened: the kernel reaches blockers that hide none of the sun "
                      "there, so the penumbra estimate is too wide.";
  limits.shadow_advice = "light in the umbra: the penumbra estimate is too wide.";
  limits.penumbra_error = kPenumbraLimit;
  limits.penumbra_advice = "the penumbra's brightness ramps over the wrong width: a hard edge means width 0 (or far "
                           "too small); a wash means too wide. It must grow with the sun's size and the blocker-receiver "
                           "distance.";
  return limits;
}

void measure_case(CheckContext& ctx, CheckResult& result, const ParamSet& p, const std::string& tag,
                  const HardLimits& limits, nlohmann::json& cases) {
  const auto m = ctx.measure(p, ctx.hooks(), "lab16_" + tag + "_" + impl_name(ctx.impl), nullptr, grading_band(),
                             kWidth, kHeight);
  grade_hard_shadow(result, tag, m.metrics, limits);
  cases.push_back({{"case", tag}, {"light_size_deg", p.get(param::light_size)},
                   {"map_size", p.get(param::shadow_map_size)}, {"render_ms", m.render_ms},
                   {"oracle_ms", m.oracle_ms}});
}

void check_pcss(CheckContext& ctx, CheckResult& result) {
  probe_penumbra(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const HardLimits limits = pcss_limits();
  nlohmann::json cases = nlohmann::json::array();
  // The lab's sun (light.size as set; its default kSunDegrees).
  measure_case(ctx, result, params, "sun", limits, cases);
  // A point-sized sun: PCSS must be the hard shadow (lab 1's bounds, no penumbra).
  ParamSet hard = params;
  hard.set("light.size", 0.0);
  measure_case(ctx, result, hard, "size0", HardLimits{}, cases);
  // Held out: other suns, sizes, map sizes and scenes, drawn from the seed.
  std::mt19937 rng = ctx.held_out_rng();
  rng.discard(4 * kProbeCases);
  std::uniform_real_distribution<float> degrees(kHeldOutMinDegrees, kHeldOutMaxDegrees);
  const auto held_out = draw_directional_cases(ctx, kHeldOut);
  for (const auto& c : held_out) {
    ParamSet p = c.apply(ctx, params);
    const float size = std::round(degrees(rng) * 10.0f) / 10.0f;
    p.set("light.size", size);
    measure_case(ctx, result, p, c.tag, limits, cases);
    nlohmann::json condition = c.to_json();
    condition["light_size_deg"] = size;
    result.conditions.push_back(condition);
  }
  ctx.use_default_scene();
  result.metrics["cases"] = cases;
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Percentage-closer soft shadows";
  lab.summary = "A sun with a size: estimate the penumbra's width from the blockers' distance, and PCSS filters over it.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSpec size = param::light_size.spec(), bias = param::shadow_bias.spec(), slope = param::shadow_slope_bias.spec();
  size.default_value = kSunDegrees;
  bias.default_value = 0.0005;  // lab 1's solution
  slope.default_value = 2.0;
  lab.params = {size, bias, slope};
  for (const auto& spec : find_shadow_test("pcss").params) lab.params.push_back(spec);
  // In the window a preset sets only its own keys over the current values (apply_preset): "see the blockers"
  // sets the lab's sun (kSunDegrees), which the view's picture in README.md shows, also after "point light".
  lab.presets = {
      {"sun", "The sun's own size, about half a degree: a narrow penumbra.", {{"light.size", "0.5"}}},
      {"wide penumbra", "A 10-degree sun: wide penumbrae, widest where the blocker is far above the ground.",
       {{"light.size", "10"}}},
      {"point light", "Size 0: PCSS is the hard shadow of lab 0.", {{"light.size", "0"}}},
      {"see the blockers", "The debug view of the blocker search: each shadowed point coloured by the blockers' "
       "mean distance above it (dark blue near, yellow at the PCSS view range).", {{"pcss.view", "blocker distance"}, {"light.size", "4"}}},
      {"see the kernel", "The debug view of your estimate: the filter's width in map texels, wider as the blocker "
       "rises; red where it would pass the 128-texel cap.", {{"pcss.view", "kernel width"}, {"light.size", "10"}}},
  };
  lab.offered_includes = {};
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.light = LightType::Directional;
    hooks.shadow_test = "pcss";  // the renderer's PCSS (shaders/shadow/pcss.glsl), around the student's estimate
    hooks.includes["lab/penumbra.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_pcss;
  // One technique for the bench: its frame at size 0 is the hard shadow (the bench's hard-truth front);
  // the bench draws it again at each sun size it grades against (it reads light.size). Not in
  // `bench --quick`: its three map sizes x five scenes, drawn again per sun size, added 20 s to the quick
  // sweep here (137.5 s against 117.7 s, load 3-4), whose time a test bounds.
  lab.bench.push_back({"pcss", "PCSS", {{"light.size", "0"}}, true, false});
  return lab;
}

}  // namespace shadowlab
