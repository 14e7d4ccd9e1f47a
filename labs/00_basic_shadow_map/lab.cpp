// Lab 0: the basic shadow map, the starting point before the numbered exercises.
// Demonstrates: a depth-only pass from the light, the [-1,1] -> [0,1] bias matrix, one depth comparison
// per fragment with a constant bias, and the debug quad showing the shadow map.
// Check: the default scene under the default light (azimuth 35, elevation 50) at the renderer's fixed
// bias 0.005, then three held-out lights, map sizes and scenes: the continuous acne and leak errors over
// interior pixels within lab 1's bounds in every case.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "grading/check.h"
#include "grading/lab.h"
#include "grading/probe.h"

namespace shadowlab {

// The GL exercise's grading (setup_check.cpp).
void check_gl_setup(CheckContext& ctx, CheckResult& result);

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = SHADOWLAB_LAB_FOLDER "/solution.glsl";

// Held-out lights stay above 30 degrees, and use lab 1's slope-scaled bias (2 texels x tan, over the
// constant): the lab's constant alone leaves acne on surfaces the light grazes at other lights and map
// sizes, which is lab 1's lesson, not this one's (the bias matrix).
constexpr double kHeldOutSlopeBias = 2.0;
const std::vector<HeldOutRange> kHeldOut = {{30.0f, 50.0f, {"512", "1024", "2048"}, {"default", "stacked"}},
                                            {50.0f, 70.0f, {"512", "1024", "2048"}, {"default", "stacked"}},
                                            {70.0f, 88.0f, {"512", "1024", "2048"}, {"default", "stacked"}}};

constexpr const char* kAdvice =
    "map the light's clip coordinates from [-1, 1] to [0, 1] (x, y and z) before reading the map and comparing.";
const HardLimits kLimits{.lit_advice = kAdvice, .shadow_advice = kAdvice};

// The shadow test alone (grading/probe.h): a light whose clip space is world space, a 64 x 64 map of
// random depths, and points inside and outside the map; each must read the texel it falls in.
constexpr int kProbeMapSize = 64;
constexpr int kProbePoints = 3000;
constexpr float kProbeBias = 0.005f;
// Points are kept this far from texel borders and from the compared depth, where rounding may decide.
constexpr float kBorderMargin = 0.05f;
constexpr float kDepthMargin = 1e-3f;
// The probe grades the lookup (the bias matrix, the texel), not the bias's value: no point lies less
// than this above its texel's stored depth, so any bias from 0 to this decides nothing here. It covers
// the slider's 0.005, the lab sheet's hard-coded `closestDepth + 0.01 > z` (course seed 003) and the
// peter-panning preset's 0.05; the pictures grade the bias.
constexpr float kProbeBiasBand = 0.05f;
// The share of probe points that may disagree with the reference: none should; a few for rounding.
constexpr double kMaxProbeMismatch = 0.002;

void probe_shadow_test(CheckContext& ctx, CheckResult& result) {
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> depths(kProbeMapSize * kProbeMapSize);
  for (auto& d : depths) d = unit(rng) < 0.5f ? 0.3f : 0.7f;
  ProbeRequest request;
  request.fragment = "shaders/probe/visibility.frag";
  std::vector<float> expected;
  std::vector<bool> inside;
  while (static_cast<int>(request.in0.size()) < kProbePoints) {
    // A texel index from 4 outside the map to 4 beyond it, a place inside it away from its borders.
    auto coordinate = [&] {
      const float texel = std::floor(unit(rng) * (kProbeMapSize + 8)) - 4.0f;
      return (texel + kBorderMargin + (1.0f - 2.0f * kBorderMargin) * unit(rng)) / kProbeMapSize;
    };
    const glm::vec3 s(coordinate(), coordinate(), -0.1f + 1.2f * unit(rng));
    const bool in = s.x >= 0 && s.x <= 1 && s.y >= 0 && s.y <= 1 && s.z >= 0 && s.z <= 1;
    float reference = 1.0f;
    if (in) {
      const int ix = std::min(static_cast<int>(s.x * kProbeMapSize), kProbeMapSize - 1);
      const int iy = std::min(static_cast<int>(s.y * kProbeMapSize), kProbeMapSize - 1);
      const float stored = depths[static_cast<std::size_t>(iy * kProbeMapSize + ix)];
      if (s.z > stored - kDepthMargin && s.z < stored + kProbeBiasBand + kDepthMargin) continue;
      reference = s.z - kProbeBias > stored ? 0.0f : 1.0f;
    }
    request.in0.push_back(glm::vec4(2.0f * s - 1.0f, 1.0f));  // world = clip: x, y, z in [-1, 1]; n.l = 1
    request.in1.push_back({0, 0, 1, 0});
    expected.push_back(reference);
    inside.push_back(in);
  }
  const GlTexture map = make_probe_depth_texture(depths, kProbeMapSize);
  const GlSampler compare = make_compare_sampler();
  request.passes.push_back([&](GLuint program) {
    bind_probe_shadow_map(program, map, compare);
    set_uniform(program, "u_light_view_proj", glm::mat4(1.0f));
    set_uniform(program, "u_bias_constant", kProbeBias);
    set_uniform(program, "u_bias_slope", 0.0f);
    set_uniform(program, "u_texel_depth", 0.0f);
  });
  const std::vector<float> v = run_probe(ctx.hooks(), request).at(0);
  double wrong_inside = 0, wrong_outside = 0, n_inside = 0, n_outside = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const bool wrong = !(std::abs(v[i] - expected[i]) <= 1e-3f);
    (inside[i] ? wrong_inside : wrong_outside) += wrong;
    (inside[i] ? n_inside : n_outside) += 1;
  }
  const std::string why = "probe: 64x64 map of random depths, points inside and outside it; 0.2 % for rounding";
  result.metrics["probe"] = {{"map_size", kProbeMapSize}, {"points_inside", n_inside}, {"points_outside", n_outside},
                             {"wrong_inside", wrong_inside}, {"wrong_outside", wrong_outside}};
  result.criteria.push_back({"probe.lookup_mismatch", wrong_inside / std::max(n_inside, 1.0), Criterion::kAtMost,
                             kMaxProbeMismatch, why,
                             "each point must read the texel it falls in: x, y and z from [-1, 1] to [0, 1] (scale 0.5, "
                             "offset 0.5), the texel at floor(uv * size), compared with the biased depth."});
  result.criteria.push_back({"probe.outside_map_mismatch", wrong_outside / std::max(n_outside, 1.0), Criterion::kAtMost,
                             kMaxProbeMismatch, why,
                             "outside the light's map nothing was drawn, so nothing can hide the point: return 1 there."});
}

void check_basic(CheckContext& ctx, CheckResult& result) {
  check_gl_setup(ctx, result);
  probe_shadow_test(ctx, result);
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  // The lab's own scene and light, then held-out lights, map sizes and scenes: the bias matrix is the
  // same for every one.
  ParamSet sloped = params;
  sloped.set("shadow.slope_bias", kHeldOutSlopeBias);
  grade_lab_and_held_out_lights(ctx, result, "lab00", "lab_light", params, sloped, kHeldOut, kLimits);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Basic shadow map";
  lab.summary = "Two passes: depth from the light, then one depth comparison per pixel.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.gl_exercise_files = {SHADOWLAB_LAB_FOLDER "/gl_shadow_target.cpp"};
  lab.gl_solution_files = {"renderer/shadow_target.cpp"};
  lab.presets = {
      {"acne", "No bias: surfaces shadow themselves in stripes.", {{"shadow.bias", "0"}},
       {.provokes = "acne", .fixed_by = "tutorial"}},
      {"peter-panning", "A huge bias under a low light, seen from the thin plate's foot: its shadow detaches from it.",
       {{"shadow.bias", "0.05"}, {"light.elevation", "20"}},
       {.provokes = "peter-panning", .fixed_by = "tutorial"}, {.camera = "eye=-1.6,0.7,2.6 target=0.1,0.1,0.4 fov=40"}},
      {"tutorial", "The tutorial's constant bias of 0.005.", {{"shadow.bias", "0.005"}}},
  };
  lab.offered_includes = {"lab/bias.glsl"};
  // The bias matrix is the lesson: the exercise's programs hold nothing that maps into the shadow map
  // for it (Features::own_shadow_coords; the audit in INSTRUCTOR.md).
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks = visibility_lab_hooks()(files);
    hooks.own_shadow_coords = true;
    return hooks;
  };
  lab.check = check_basic;
  return lab;
}

}  // namespace shadowlab
