// Lab 11: billboards from a geometry shader, and their shadows (the GS lecture).
// Demonstrates: one point in, an upright quad out (a tree with an alpha cut-out), turned toward the
// camera in the view; in the shadow pass the same quad must turn toward the LIGHT and cut out the same
// points: a quad turned toward the camera casts a shadow that swims as the camera moves, and a quad
// without the alpha test casts a solid rectangle.
// Check: probes of the student's two functions (the quad's orientation, size and independence of the
// camera on chosen trees, lights and eyes; the alpha test on a grid of points and cutoffs), then the
// shadows against the oracle, whose trees are the light-facing quads with the same cut-out function
// (an Embree filter, renderer/billboards.h), from two cameras, with the shadow map compared texel by
// texel between them, and under held-out lights, map sizes, cutoffs and tree sizes.
#include "grading/lab.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "grading/check.h"
#include "grading/probe.h"
#include "renderer/billboards.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/billboard/shadow_quad.glsl";

// The trees of the default scene: on the open ground between its objects.
const std::vector<glm::vec3>& trees() {
  static const std::vector<glm::vec3> bases = {
      {-4.3f, 0.0f, 0.6f}, {-4.6f, 0.0f, -3.8f}, {-0.6f, 0.0f, -4.2f}, {3.6f, 0.0f, -4.3f}, {4.4f, 0.0f, 0.4f},
      {4.2f, 0.0f, 3.9f},  {0.3f, 0.0f, 4.3f},   {-4.0f, 0.0f, 4.4f},  {-0.9f, 0.0f, -0.2f}};
  return bases;
}

// The probes.
constexpr int kQuadCases = 256;          // trees, lights and eyes drawn from the seed
constexpr int kAlphaGrid = 64;           // uv points per side for the alpha test
constexpr float kCutoffs[] = {0.2f, 0.35f, 0.5f, 0.65f, 0.8f};
constexpr float kAlphaTie = 1e-4f;       // |alpha - cutoff| below this: float rounding decides, not graded
constexpr float kProbeSizes[2][2] = {{1.4f, 2.0f}, {0.9f, 2.6f}};  // width, height

// The limits (measured: INSTRUCTOR.md, docs/measured/lab_11.json).
constexpr double kMaxOrientationDeg = 0.5;   // the quad's normal and up against the light-facing upright quad's
constexpr double kMaxSizeError = 0.01;       // |right| against the width, |up| against the height, relative
constexpr double kMaxProbeCameraChange = 1e-5;  // world units: the quad for two eyes
constexpr double kMaxAlphaMismatch = 0.001;     // share of (uv, cutoff) points kept or cut wrongly
constexpr double kMaxMapChange = 0.0;           // share of shadow-map texels changed between the two cameras

// The second camera (the first is the default framing: yaw 30, pitch 30 degrees).
constexpr float kCameraBYaw = -70.0f, kCameraBPitch = 45.0f;

// The held-out lights' elevation ranges (low, then high), and their cutoffs and tree sizes.
constexpr float kHeldOutElevation[3] = {25.0f, 45.0f, 70.0f};
constexpr float kHeldOutCutoff[2] = {0.3f, 0.7f};
constexpr float kHeldOutWidth[2] = {1.0f, 1.8f};
constexpr float kHeldOutHeight[2] = {1.6f, 2.2f};

Features lab_hooks(const SlotFiles& files) {
  Features hooks;
  hooks.includes["lab/billboard.glsl"] = files.at(0).string();
  hooks.light = LightType::Directional;
  hooks.billboards = trees();
  return hooks;
}

// The oracle for these parameters: the scene as drawn, and the trees as the light should see them.
std::unique_ptr<Oracle> trees_oracle(CheckContext& ctx, const ParamSet& params) {
  Scene scene = frame_scene(ctx.scene(), adds_ground(ctx.scene(), params), params.get(param::scene_blend_casts));
  const glm::vec3 to_light = direction_from_angles(params.get(param::light_azimuth), params.get(param::light_elevation));
  scene.meshes.push_back(billboard_light_quads(trees(), billboard_size(params), to_light));
  return std::make_unique<Oracle>(scene);
}

// Angle in degrees between two directions (1 for parallel, either sign with `either_sign`); 90 for a zero
// or non-finite vector.
double angle_deg(glm::dvec3 a, glm::dvec3 b, bool either_sign) {
  const double la = glm::length(a), lb = glm::length(b);
  if (!(la > 1e-12) || !(lb > 1e-12) || !std::isfinite(la)) return 90.0;
  double c = glm::dot(a, b) / (la * lb);
  if (either_sign) c = std::abs(c);
  return glm::degrees(std::acos(std::clamp(c, -1.0, 1.0)));
}

// A quad the probe turns: a tree's base and the direction to the light.
struct QuadCase {
  glm::vec3 base, to_light;
};

// Pass 0: eye 0, the first size; pass 1: eye 1, the same size; pass 2: eye 0, the second size.
constexpr int kPassEye[3] = {0, 1, 0}, kPassSize[3] = {0, 0, 1};

struct QuadErrors {
  double orientation = 0.0, size_error = 0.0, camera_change = 0.0;
};

// The quads' orientation, size and change with the eye, over the three passes.
QuadErrors quad_errors(const std::vector<QuadCase>& quads, const std::vector<std::vector<float>>& out) {
  QuadErrors q;
  double& orientation = q.orientation;
  double& size_error = q.size_error;
  double& camera_change = q.camera_change;
  for (int p = 0; p < 3; ++p) {
    const double w = kProbeSizes[kPassSize[p]][0], h = kProbeSizes[kPassSize[p]][1];
    for (std::size_t i = 0; i < quads.size(); ++i) {
      const float* v = &out[static_cast<std::size_t>(p)][6 * i];
      const glm::dvec3 right(v[0], v[1], v[2]), up(v[3], v[4], v[5]);
      const glm::dvec3 l(quads[i].to_light);
      const glm::dvec3 right_ref = glm::normalize(glm::dvec3(l.z, 0.0, -l.x)) * w, up_ref(0.0, h, 0.0);
      orientation = std::max({orientation, angle_deg(glm::cross(right, up), glm::cross(right_ref, up_ref), true),
                              angle_deg(up, up_ref, false)});
      const double lr = glm::length(right), lu = glm::length(up);
      double e = std::max(std::abs(lr - w) / w, std::abs(lu - h) / h);
      if (lr > 0.0 && lu > 0.0) e = std::max(e, std::abs(glm::dot(right, up)) / (lr * lu));
      size_error = std::max(size_error, std::isfinite(e) ? e : 1e30);
      if (p == 1)
        for (int k = 0; k < 6; ++k) {
          const double d = std::abs(static_cast<double>(v[k]) - out[0][6 * i + static_cast<std::size_t>(k)]);
          camera_change = std::max(camera_change, std::isfinite(d) ? d : 1e30);
        }
    }
  }
  if (!std::isfinite(orientation)) orientation = 90.0;
  return q;
}

void probe_criteria(CheckResult& result, const QuadErrors& q, double mismatch) {
  const double orientation = q.orientation, size_error = q.size_error, camera_change = q.camera_change;
  auto& c = result.criteria;
  c.push_back({"quad.orientation", orientation, Criterion::kAtMost, kMaxOrientationDeg,
               "the largest angle between your quad's normal and the upright quad turned toward the light (either "
               "side), or between your up and world up, over trees, lights and eyes drawn from the seed",
               "turn the quad about the vertical toward the light: right is the horizontal perpendicular of "
               "to_light, up is world up. The camera has nothing to do with the shadow."});
  c.push_back({"quad.size", size_error, Criterion::kAtMost, kMaxSizeError,
               "|right| against size.x, |up| against size.y (relative), and how far right and up are from square",
               "make right size.x long and up size.y long, at a right angle: the view's tree has that size."});
  c.push_back({"quad.follows_camera", camera_change, Criterion::kAtMost, kMaxProbeCameraChange,
               "the largest change of right or up (world units) when only the eye moves",
               "the shadow pass's quad must not depend on the eye: a shadow that turns with the camera swims as "
               "the camera moves. Turn it toward the light."});
  c.push_back({"alpha_test.mismatch", mismatch, Criterion::kAtMost, kMaxAlphaMismatch,
               "share of points of a 64 x 64 grid, at cutoffs 0.2-0.8, that the shadow pass keeps or cuts "
               "otherwise than the view (alpha >= cutoff is kept); ties within 1e-4 not graded",
               "discard what the view discards: keep a point when billboard_alpha(uv) >= cutoff, with the cutoff "
               "you are given."});
}

void check_probes(CheckContext& ctx, CheckResult& result, const Features& hooks) {
  std::mt19937 rng(ctx.seed * 7919u + 11u);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec4> in0, in1;
  // The quads: a tree, a light from any azimuth and 15-75 degrees up, each of the six components.
  std::vector<QuadCase> quads;
  for (int i = 0; i < kQuadCases; ++i) {
    const glm::vec3 base(10.0f * unit(rng) - 5.0f, 0.5f * unit(rng), 10.0f * unit(rng) - 5.0f);
    const glm::vec3 to_light = direction_from_angles(360.0f * unit(rng), 15.0f + 60.0f * unit(rng));
    quads.push_back({base, to_light});
    for (int k = 0; k < 6; ++k) {
      in0.push_back(glm::vec4(base, 0.0f));
      in1.push_back(glm::vec4(to_light, static_cast<float>(k)));
    }
  }
  // Two eyes, drawn from the seed: 6-12 units from the scene's centre, 10-60 degrees up.
  glm::vec3 eyes[2];
  for (auto& eye : eyes)
    eye = (6.0f + 6.0f * unit(rng)) * direction_from_angles(360.0f * unit(rng), 10.0f + 50.0f * unit(rng));
  // The alpha test on a grid of uv points, at each cutoff.
  const std::size_t a0 = in0.size();
  for (float cutoff : kCutoffs)
    for (int y = 0; y < kAlphaGrid; ++y)
      for (int x = 0; x < kAlphaGrid; ++x) {
        in0.push_back({(x + 0.5f) / kAlphaGrid, (y + 0.5f) / kAlphaGrid, cutoff, 0.0f});
        in1.push_back({0.0f, 0.0f, 0.0f, -1.0f});
      }
  ProbeRequest request;
  request.fragment = "shaders/probe/billboard.frag";
  request.in0 = in0;
  request.in1 = in1;
  for (int p = 0; p < 3; ++p)
    request.passes.push_back([&, p](GLuint program) {
      set_uniform(program, "u_probe_eye", eyes[kPassEye[p]]);
      set_uniform(program, "u_probe_size", glm::vec3(kProbeSizes[kPassSize[p]][0], kProbeSizes[kPassSize[p]][1], 0.0f));
    });
  const std::vector<std::vector<float>> out = run_probe(hooks, request);

  const QuadErrors q = quad_errors(quads, out);
  const double orientation = q.orientation, size_error = q.size_error, camera_change = q.camera_change;
  long mismatched = 0, graded = 0;
  for (std::size_t i = a0; i < in0.size(); ++i) {
    const float alpha = billboard_alpha({in0[i].x, in0[i].y}), cutoff = in0[i].z;
    if (std::abs(alpha - cutoff) < kAlphaTie) continue;
    ++graded;
    if ((out[0][i] > 0.5f) != (alpha >= cutoff)) ++mismatched;
  }
  const double mismatch = graded > 0 ? static_cast<double>(mismatched) / static_cast<double>(graded) : 1.0;

  result.conditions.push_back({{"tag", "probe"}, {"seed", ctx.seed}, {"quads", kQuadCases},
                               {"eyes", {{eyes[0].x, eyes[0].y, eyes[0].z}, {eyes[1].x, eyes[1].y, eyes[1].z}}}});
  result.metrics["probe"] = {{"orientation_deg", orientation}, {"size_error", size_error},
                             {"camera_change", camera_change}, {"alpha_mismatch", mismatch}, {"alpha_points", graded}};
  std::printf("    probe: orientation %.3g deg, size %.3g, camera change %.3g, alpha test wrong at %.4f of %ld points\n",
              orientation, size_error, camera_change, mismatch, graded);
  probe_criteria(result, q, mismatch);
}

// One view of the trees' shadows, graded against the oracle with the light-facing trees.
CheckContext::Measurement shoot(CheckContext& ctx, const ParamSet& params, const Features& hooks, const std::string& name,
                                const OrbitCamera& camera) {
  const std::unique_ptr<Oracle> oracle = trees_oracle(ctx, params);
  return ctx.measure(params, hooks, name, nullptr, grading_band(), 960, 540, &camera, oracle.get());
}

void check_billboards(CheckContext& ctx, CheckResult& result) {
  const Features hooks = ctx.hooks();
  ctx.use(hooks);
  check_probes(ctx, result, hooks);

  const std::string impl = impl_name(ctx.impl);
  const ParamSet params = ctx.params();
  const HardLimits limits{0.001, 0.005, "lab 1's bounds: 0.1 % acne, 0.5 % leak, interior pixels",
                          "the shadow has tree where the light-facing tree has none: cut out what the view cuts out, "
                          "and turn the quad toward the light.",
                          "light passes where the light-facing tree casts shadow: turn the quad toward the light, at "
                          "the view's size."};
  // Two cameras: the default framing, and one 100 degrees round the other way and higher, looking toward
  // the light (from the light's side the casters hide their own shadows). The shadow map must be the
  // same texel for texel.
  const Bounds box = ctx.scene().bounds();
  const OrbitCamera camera_a = OrbitCamera::framing(box), camera_b = OrbitCamera::framing(box, kCameraBYaw, kCameraBPitch);
  const auto a = shoot(ctx, params, hooks, "lab11_camera_a_" + impl, camera_a);
  grade_hard_shadow(result, "camera_a", a.metrics, limits);
  result.metrics["camera_a"]["render_ms"] = a.render_ms;
  result.metrics["camera_a"]["oracle_ms"] = a.oracle_ms;
  int size_a = 0, size_b = 0;
  const std::vector<float> map_a = ctx.renderer.read_shadow_depth(&size_a);
  const auto b = shoot(ctx, params, hooks, "lab11_camera_b_" + impl, camera_b);
  grade_hard_shadow(result, "camera_b", b.metrics, limits);
  const std::vector<float> map_b = ctx.renderer.read_shadow_depth(&size_b);
  double changed = 1.0;
  if (size_a == size_b && map_a.size() == map_b.size() && !map_a.empty()) {
    long n = 0;
    for (std::size_t i = 0; i < map_a.size(); ++i) n += map_a[i] != map_b[i];
    changed = static_cast<double>(n) / static_cast<double>(map_a.size());
  }
  result.metrics["shadow_map"] = {{"texels", map_a.size()}, {"changed_share", changed}};
  result.criteria.push_back({"shadow_map.follows_camera", changed, Criterion::kAtMost, kMaxMapChange,
                             "share of shadow-map texels that differ between the two cameras' frames (same light)",
                             "the shadow map changed when only the camera moved: the shadow pass's quad must "
                             "face the light, not the eye."});

  // Held-out: other lights and map sizes (draw_directional_cases), each with another cutoff and tree size.
  std::mt19937 rng(ctx.seed * 7919u + 12u);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const std::vector<HeldOutRange> ranges = {{kHeldOutElevation[0], kHeldOutElevation[1], {"1024", "2048"}, {"default"}},
                                            {kHeldOutElevation[1], kHeldOutElevation[2], {"1024", "2048"}, {"default"}}};
  int k = 0;
  for (const DirectionalCase& c : draw_directional_cases(ctx, ranges)) {
    ParamSet p = c.apply(ctx, params);
    const float cutoff = kHeldOutCutoff[k % 2], width = kHeldOutWidth[0] + (kHeldOutWidth[1] - kHeldOutWidth[0]) * unit(rng),
                height = kHeldOutHeight[0] + (kHeldOutHeight[1] - kHeldOutHeight[0]) * unit(rng);
    ++k;
    p.set("billboard.cutoff", cutoff);
    p.set("billboard.width", width);
    p.set("billboard.height", height);
    const auto h = shoot(ctx, p, hooks, "lab11_" + c.tag + "_" + impl, camera_a);
    grade_hard_shadow(result, c.tag, h.metrics, limits);
    nlohmann::json j = c.to_json();
    j["cutoff"] = cutoff;
    j["tree_width"] = width;
    j["tree_height"] = height;
    result.conditions.push_back(j);
  }
  ctx.use_default_scene();
  std::printf("    shadows: camera A lit %.5f shadow %.5f, camera B lit %.5f shadow %.5f, map texels changed %.5f\n",
              a.metrics.lit_error, a.metrics.shadow_error, b.metrics.lit_error, b.metrics.shadow_error, changed);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Billboards from a geometry shader, and their shadows";
  lab.summary = "Trees as points a geometry shader turns into cut-out quads; their shadow pass faces the light and alpha-tests.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = billboard_param_specs();
  lab.presets = {
      {"trees", "The trees and their shadows.", {{"billboard.show_shadow_quads", "0"}}},
      {"shadow quads", "The quads your shadow pass draws, in magenta over the view: orbit the camera and watch them.",
       {{"billboard.show_shadow_quads", "1"}}},
      {"low sun", "A low light: long shadows, the quad seen from the side by the camera.",
       {{"light.elevation", "25"}, {"billboard.show_shadow_quads", "0"}}},
      {"thin crowns", "A high cutoff: more of each crown is cut out, in the view and in the shadow.",
       {{"billboard.cutoff", "0.75"}}},
  };
  lab.offered_includes = {};
  lab.make_hooks = lab_hooks;
  lab.check = check_billboards;
  return lab;
}

}  // namespace shadowlab
