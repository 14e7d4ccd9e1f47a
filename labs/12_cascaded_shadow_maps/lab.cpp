// Lab 12: cascaded shadow maps (beyond the course). The camera's view range is split into cascades (the
// practical blend of uniform and logarithmic splits), each with an ortho light box fitted to its
// slice's bounding sphere and snapped to whole texels; the lit pass picks a cascade per pixel.
// The student writes the split distances and the box (core/cascades.cpp is the solution), in C++:
// both run on the CPU once per cascade and frame, as they do in every engine, and lab 2's path grades a
// submitted C++ file in a program of its own.
// Check: (1) the splits against the formula at held-out near/far/lambda/count; (2) the box, over
// camera turns and moves: it holds the slice, keeps its size, and moves by whole texels only; (3) no
// shimmer: under a still view, a sequence of small moves and turns of the camera the cascades follow
// changes no pixel's result within its cascade; (4) the error against the oracle below lab 2's single
// fitted map at the same total texels, on the default scene and the PalmTree.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <random>

#include "labs/12_cascaded_shadow_maps/cascades_lab.h"
#include "grading/check.h"
#include "grading/cpp_exercise.h"
#include "grading/lab.h"
#include "grading/light_view_answer.h"
#include "renderer/cascade_pass.h"
#include "core/gltf_loader.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.cpp";
constexpr const char* kSolution = "core/cascades.cpp";  // practical_splits, fit_cascade_sphere
constexpr const char* kPalmTree = "assets/models/PalmTree/PalmTree.gltf";

// (1) Splits: a distance off by more than this share of the far plane is wrong (float32 arithmetic of a
// right answer stays below 1e-6 of it).
constexpr double kSplitTolerance = 1e-4;
constexpr int kSplitCases = 40;
constexpr float kProbeNearMin = 0.01f;  // the probe's near planes: kProbeNearMin..5, far / near 5..5000
constexpr double kMaxSplitMismatch = 0;  // share of the cases with a wrong distance: none
// (2) The box: a corner of the slice more than this far outside [-1, 1] (NDC) is outside; a size change
// of more than 0.01 texel across the map is a change; a grid phase that moves by more than 0.01 texel
// between two poses is a crawl.
constexpr double kNdcTolerance = 1e-4;
constexpr double kTexelTolerance = 0.01;
constexpr int kFitMapSize = 512;
constexpr int kMaxBadSlices = 0;  // slices outside, size changes, crawls, NaN, wrong world_size: none
// (3) Shimmer: the share of pixels, shaded from the same cascade before and after a small camera move,
// whose result changed. Measured (lab README): 0 for the solution; the stock's tight box 0.3-1 %.
constexpr double kMaxShimmer = 1e-4;
// (4) The error (acne + leak over all pixels) against lab 2's single fitted map at the same total texels
// (shadow.map_size x shadow.map_size shared by the cascades), in a band of 2 screen pixels (as lab 2).
constexpr int kBudget = 1024;  // texels per side of the single map (shadow.map_size)
constexpr int kBandPixels = 2;
constexpr double kMaxErrorRatio = 0.9;
// Where cascades are meant to work: a camera standing in the scene, looking across it (on the default
// scene: at the ground's corner, at 1.3 units, 45 deg field of view). From outside, framing the whole
// scene, one fitted map is as sharp (INSTRUCTOR.md; the benchmark's scenes).
constexpr float kEyeX = 3.3f, kEyeY = 0.9f, kEyeZ = 3.8f;

OrbitCamera ground_camera(const Bounds& scene) {
  return OrbitCamera::looking({kEyeX, kEyeY, kEyeZ}, {1.2f, 0.3f, 1.4f}, 45.0f, scene);
}
// On the PalmTree: a camera on the island looking at the palms (their trunks stand near the origin,
// 3.4 units high), near and far planes from the whole scene (the sea reaches 196 units out).
constexpr float kPalmEyeX = 6.0f, kPalmEyeY = 2.5f, kPalmEyeZ = 9.0f;
constexpr double kPalmElevation = 30.0;  // light elevation (deg): long shadows across the island

OrbitCamera palm_camera(const Bounds& scene) {
  return OrbitCamera::looking({kPalmEyeX, kPalmEyeY, kPalmEyeZ}, {-2.5f, 1.0f, 1.0f}, 45.0f, scene);
}

class SubmittedCascades {
 public:
  explicit SubmittedCascades(const std::filesystem::path& file) : program_(spec(file)) {}
  std::vector<CascadeAnswer> call_many(const std::vector<CascadeCall>& calls) { return program_.call_many<CascadeAnswer>(calls); }
  CascadeAnswer call(const CascadeCall& c) { return program_.call<CascadeAnswer>(c); }

 private:
  static CppExerciseSpec spec(const std::filesystem::path& file) {
    CppExerciseSpec spec;
    spec.source = file;
    spec.display_name = kExercise;
    spec.host = "12_cascaded_shadow_maps";
    spec.headers = {"labs/12_cascaded_shadow_maps/cascades_lab.h", "core/cascades.h", "core/light.h",
                    "core/scene.h", "core/params.h"};
    spec.offered = {"shadowlab::orthonormal_basis", "shadowlab::direction_from_angles"};
    return spec;
  }
  CppExercise program_;
};

CascadeCall splits_call(float near_plane, float far_plane, int count, float lambda) {
  CascadeCall c{};
  c.kind = 0;
  c.near_plane = near_plane;
  c.far_plane = far_plane;
  c.count = count;
  c.lambda = lambda;
  return c;
}

CascadeCall fit_call(const FrustumCorners& slice, const glm::vec3& to_light, int map_size, const Bounds& scene) {
  CascadeCall c{};
  c.kind = 1;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) c.corners[3 * i + k] = slice[static_cast<std::size_t>(i)][k];
  for (int k = 0; k < 3; ++k) {
    c.to_light[k] = to_light[k];
    c.box_min[k] = scene.min[k];
    c.box_max[k] = scene.max[k];
  }
  c.map_size = map_size;
  return c;
}

std::vector<float> splits_of(const CascadeAnswer& a) {
  return std::vector<float>(a.splits, a.splits + std::clamp(a.split_count, 0, kMaxCascades + 1));
}

std::shared_ptr<SubmittedCascades> submitted(const std::filesystem::path& file) { return built_once<SubmittedCascades>(file); }

struct CascadeFns {
  CascadeSplitFn splits;
  CascadeFitFn fit;
};

// The functions in the slot: the exercise and the solution are compiled in (edit, rebuild, Check); any
// other file is a submission's, built and called on its own.
CascadeFns fns_for_file(const std::filesystem::path& file) {
  if (file == kExercise) return {cascade_splits_exercise, cascade_fit_exercise};
  if (file == kSolution) return {practical_splits, fit_cascade_sphere};
  auto s = submitted(file);
  return {[s](float n, float f, int count, float lambda) { return splits_of(s->call(splits_call(n, f, count, lambda))); },
          [s](const FrustumCorners& slice, const glm::vec3& to_light, int size, const Bounds& scene) {
            return light_view_of(s->call(fit_call(slice, to_light, size, scene)));
          }};
}

// What the renderer gets: the splits always count + 1 long (a wrong count is graded by the probe, not
// left to stop the frame).
Features hooks_for(const CascadeFns& fns) {
  Features hooks;
  hooks.technique = ShadowTechnique::CascadedShadowMaps;
  hooks.cascade_splits = [splits = fns.splits](float n, float f, int count, float lambda) {
    std::vector<float> s = splits(n, f, count, lambda);
    s.resize(static_cast<std::size_t>(count) + 1, f);
    return s;
  };
  hooks.cascade_fit = fns.fit;
  return hooks;
}

// (1) The splits against the formula at held-out near, far, lambda and count.
void grade_splits(CheckContext& ctx, CheckResult& result, const CascadeFns& fns, bool compiled_in) {
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<CascadeCall> calls;
  for (int i = 0; i < kSplitCases; ++i) {
    const float n = std::exp(std::log(kProbeNearMin) + unit(rng) * std::log(5.0f / kProbeNearMin));
    const float f = n * std::exp(std::log(5.0f) + unit(rng) * std::log(1000.0f));
    const int count = 1 + static_cast<int>(unit(rng) * kMaxCascades) % kMaxCascades;
    const float lambda = i == 0 ? 0.0f : i == 1 ? 1.0f : unit(rng);
    calls.push_back(splits_call(n, f, std::max(count, i < 2 ? 4 : 1), lambda));
  }
  std::vector<std::vector<float>> answers;
  if (compiled_in) {
    for (const auto& c : calls) answers.push_back(fns.splits(c.near_plane, c.far_plane, c.count, c.lambda));
  } else {
    for (const auto& a : submitted(ctx.graded.at(0))->call_many(calls)) answers.push_back(splits_of(a));
  }
  int wrong = 0, wrong_count = 0;
  double worst = 0.0;
  nlohmann::json first_wrong;
  for (std::size_t i = 0; i < calls.size(); ++i) {
    const CascadeCall& c = calls[i];
    const std::vector<float> want = practical_splits(c.near_plane, c.far_plane, c.count, c.lambda);
    bool ok = answers[i].size() == want.size();
    if (!ok) ++wrong_count;
    for (std::size_t k = 0; ok && k < want.size(); ++k) {
      const double err = std::abs(static_cast<double>(answers[i][k]) - want[k]) / c.far_plane;
      worst = std::max(worst, std::isfinite(err) ? err : 1e30);
      if (!(err <= kSplitTolerance)) ok = false;
    }
    if (!ok) {
      ++wrong;
      if (first_wrong.is_null())
        first_wrong = {{"near", c.near_plane}, {"far", c.far_plane}, {"count", c.count}, {"lambda", c.lambda},
                       {"expected", want}, {"got", answers[i]}};
    }
  }
  result.metrics["splits"] = {{"cases", calls.size()}, {"wrong", wrong}, {"wrong_count", wrong_count},
                              {"worst_error_over_far", worst}, {"first_wrong", first_wrong}};
  result.criteria.push_back({"splits.formula_mismatch", static_cast<double>(wrong) / static_cast<double>(calls.size()),
                             Criterion::kAtMost, kMaxSplitMismatch,
                             "every distance within 1e-4 of the far plane of lambda C_log + (1 - lambda) C_uni, count + 1 of them",
                             "C_i = lambda n (f / n)^(i / N) + (1 - lambda) (n + (f - n) i / N) for i = 0..N: lambda 0 is "
                             "uniform, 1 logarithmic; return N + 1 distances."});
}

// The grid phase of the map at a world point: where the point falls within its texel (0..1 per axis).
glm::dvec2 texel_phase(const LightView& v, const glm::vec3& point, int map_size) {
  const glm::dvec4 p = glm::dmat4(v.view_projection()) * glm::dvec4(glm::dvec3(point), 1.0);
  const glm::dvec2 t = (glm::dvec2(p) * 0.5 + 0.5) * static_cast<double>(map_size);
  return t - glm::floor(t);
}
double phase_distance(const glm::dvec2& a, const glm::dvec2& b) {
  double worst = 0.0;
  for (int k = 0; k < 2; ++k) {
    const double d = std::abs(a[k] - b[k]);
    worst = std::max(worst, std::min(d, 1.0 - d));
  }
  return worst;
}

// What grade_fit counts over every slice it fits.
struct FitTally {
  int slices = 0, outside = 0, depth_outside = 0, size_changes = 0, crawls = 0, world_size_wrong = 0, non_finite = 0;
  double worst_size = 0.0, worst_crawl = 0.0;
};

// One cascade's box `v` for `slice` at this pose, against the scene and against the same cascade's box at
// the first pose (`first`, kept at pose 0).
void grade_slice(const LightView& v, const FrustumCorners& slice, const Bounds& scene, int pose, LightView& first,
                 FitTally& t) {
  const glm::dmat4 m(v.view_projection());
  ++t.slices;
  bool finite = true;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) finite = finite && std::isfinite(m[a][b]);
  if (!finite) {
    ++t.non_finite;
    return;
  }
  bool out = false, deep = false;
  for (const glm::vec3& corner : slice) {
    const glm::dvec4 p = m * glm::dvec4(glm::dvec3(corner), 1.0);
    out = out || std::abs(p.x) > 1.0 + kNdcTolerance || std::abs(p.y) > 1.0 + kNdcTolerance;
  }
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 p = m * glm::dvec4(glm::dvec3(scene.corner(i)), 1.0);
    deep = deep || std::abs(p.z) > 1.0 + kNdcTolerance;
  }
  t.outside += out;
  t.depth_outside += deep;
  const double size = 2.0 / std::abs(static_cast<double>(v.projection[0][0]));
  if (std::abs(v.world_size.x - size) > 1e-3 * size) ++t.world_size_wrong;
  if (pose == 0) {
    first = v;
    return;
  }
  const LightView& f = first;
  const double size0 = 2.0 / std::abs(static_cast<double>(f.projection[0][0]));
  const double size_texels = std::abs(size - size0) / size0 * kFitMapSize;
  t.worst_size = std::max(t.worst_size, size_texels);
  if (size_texels > kTexelTolerance) {
    ++t.size_changes;
    return;  // a box of another size has another grid: its phase says nothing
  }
  const double crawl = phase_distance(texel_phase(v, scene.center(), kFitMapSize), texel_phase(f, scene.center(), kFitMapSize));
  t.worst_crawl = std::max(t.worst_crawl, crawl);
  if (crawl > kTexelTolerance) ++t.crawls;
}

void report_fit(CheckResult& result, const FitTally& t) {
  result.metrics["fit"] = {{"slices", t.slices}, {"non_finite", t.non_finite}, {"slice_outside", t.outside},
                           {"casters_outside_depth", t.depth_outside}, {"size_changes", t.size_changes},
                           {"worst_size_change_texels", t.worst_size}, {"texel_crawl", t.crawls},
                           {"worst_crawl_texels", t.worst_crawl}, {"world_size_wrong", t.world_size_wrong}};
  const auto add = [&](const char* name, int value, const char* why, const char* advice) {
    result.criteria.push_back({std::string("fit.") + name, static_cast<double>(value), Criterion::kAtMost,
                                static_cast<double>(kMaxBadSlices), why, advice});
  };
  add("non_finite_boxes", t.non_finite, "no NaN or Inf in any cascade's matrix", "");
  add("slice_outside", t.outside, "every corner of the slice inside the box (within 1e-4)",
      "the box must hold the whole slice: the sphere's radius, plus one texel on each side for the snap "
      "(texel = 2 r / (map_size - 2), half-size texel * map_size / 2).");
  add("casters_outside_depth", t.depth_outside, "every corner of the scene's box within the depth range",
      "fit the depth to the scene's box along the light (lab 2), not to the slice: casters outside the slice "
      "still cast into it.");
  add("size_changes", t.size_changes, "the box keeps its size (within 0.01 texel) when the camera turns",
      "fit the slice's bounding sphere, not a tight box: the sphere's radius does not depend on where the camera looks.");
  add("texel_crawl", t.crawls, "the box moves by whole texels (within 0.01) when the camera moves",
      "snap the centre's light-space coordinates (dot with X and Y) to multiples of the texel, 2 r / (map_size - 2).");
  add("world_size_mismatch", t.world_size_wrong, "world_size = the box's footprint (the bias reads it)",
      "set world_size = (2 r, 2 r).");
}

// (2) The box: over turns and moves of the camera, for a few light directions.
void grade_fit(CheckContext& ctx, CheckResult& result, const CascadeFns& fns) {
  const Bounds scene = ctx.scene().bounds();
  const float extent = glm::length(scene.extent());
  const OrbitCamera base = ground_camera(scene);
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec3> lights = {direction_from_angles(ctx.params().get(param::light_azimuth), ctx.params().get(param::light_elevation))};
  for (int i = 0; i < 2; ++i) lights.push_back(direction_from_angles(360.0f * unit(rng), 15.0f + 70.0f * unit(rng)));
  constexpr int kPoses = 8;
  constexpr int kCount = 4;
  FitTally tally;
  for (const glm::vec3& to_light : lights) {
    for (int motion = 0; motion < 2; ++motion) {  // 0: turns (yaw and pitch), 1: moves (the target)
      std::vector<LightView> first(kCount);
      for (int pose = 0; pose < kPoses; ++pose) {
        OrbitCamera cam = base;
        if (motion == 0) {
          cam.yaw_deg += 0.73f * pose;
          cam.pitch_deg += 0.41f * pose;
        } else {
          cam.target += glm::vec3(0.0137f, 0.0031f, -0.0089f) * (extent * pose);
        }
        const glm::mat4 view = cam.view(), proj = cam.projection(16.0f / 9.0f);
        const std::vector<float> splits = practical_splits(cam.near_plane, cam.far_plane, kCount, 0.75f);
        for (int c = 0; c < kCount; ++c) {
          const FrustumCorners slice = frustum_slice(view, proj, splits[static_cast<std::size_t>(c)], splits[static_cast<std::size_t>(c) + 1]);
          const LightView v = fns.fit(slice, to_light, kFitMapSize, scene);
          grade_slice(v, slice, scene, pose, first[static_cast<std::size_t>(c)], tally);
        }
      }
    }
  }
  report_fit(result, tally);
}

// (3) Shimmer: a still view; the camera the cascades follow moves and turns a little, pose by pose.
// A pixel shaded from the same cascade before and after must keep its result.
void grade_shimmer(CheckContext& ctx, CheckResult& result, const ParamSet& params, const Features& hooks) {
  ctx.use(hooks);
  const Bounds scene = ctx.scene().bounds();
  const float extent = glm::length(scene.extent());
  FrameRequest request;
  request.camera = ground_camera(scene);
  request.width = 960;
  request.height = 540;
  request.gbuffer = true;
  const glm::vec3 to_light = direction_from_angles(params.get(param::light_azimuth), params.get(param::light_elevation));
  auto frame = [&](const OrbitCamera& cascade_camera) {
    request.cascade_camera = cascade_camera;
    ctx.renderer.render(params, request);
    const auto* pass = dynamic_cast<const CascadePass*>(ctx.renderer.shadow_pass());
    if (!pass) throw std::logic_error("lab 12's hooks do not select the cascade pass");
    return std::make_pair(ctx.renderer.read_visibility(), pass->cascades());
  };
  const GBuffer g = [&] {
    frame(request.camera);
    return ctx.renderer.read_gbuffer();
  }();
  const auto [vis0, cascades0] = frame(request.camera);
  std::uint64_t compared = 0, changed = 0;
  constexpr int kPoses = 6;
  for (int pose = 1; pose <= kPoses; ++pose) {
    OrbitCamera cam = request.camera;
    cam.target += glm::vec3(0.0113f, 0.0021f, -0.0071f) * (extent * pose);
    cam.yaw_deg += 0.37f * pose;
    cam.pitch_deg += 0.23f * pose;
    const auto [vis, cascades] = frame(cam);
    for (std::size_t i = 0; i < vis.size(); ++i) {
      if (!g.covered[i] || glm::dot(g.normal[i], to_light) <= 0.0f) continue;
      if (cascades.cascade_of(g.position[i]) != cascades0.cascade_of(g.position[i])) continue;
      ++compared;
      if ((vis[i] < 0.5f) != (vis0[i] < 0.5f)) ++changed;
    }
  }
  const double share = compared > 0 ? static_cast<double>(changed) / static_cast<double>(compared) : 1.0;
  result.metrics["shimmer"] = {{"poses", kPoses}, {"compared_pixels", compared}, {"changed_pixels", changed}, {"share", share}};
  std::printf("    shimmer: %llu of %llu pixels (same cascade) changed over %d small camera moves\n",
              static_cast<unsigned long long>(changed), static_cast<unsigned long long>(compared), kPoses);
  result.criteria.push_back({"shimmer.changed_share", share, Criterion::kAtMost, kMaxShimmer,
                             "a still view, the cascades' camera moved and turned a little six times: results within a "
                             "cascade must not change (measured: 0 for the solution)",
                             "a sphere's box of constant size, moved by whole texels in light space: then a map is only "
                             "ever shifted by whole texels and every comparison is the same."});
}

// (4) Error against the oracle: the cascades against lab 2's single fitted map of the same total texels.
// With `near_depth` > 0 only the pixels nearer the camera than that (view depth) are graded, and the
// whole view is reported.
struct ErrorPair {
  Metrics cascades, single;
  static double error(const Metrics& m) { return m.acne_rate_all + m.leak_rate_all; }
  double ratio() const { return error(single) > 0 ? error(cascades) / error(single) : 1.0; }
  nlohmann::json to_json() const {
    return {{"cascades", shadowlab::to_json(cascades)}, {"single_map", shadowlab::to_json(single)},
            {"error_cascades", error(cascades)}, {"error_single_map", error(single)}, {"error_ratio", ratio()}};
  }
};

void compare_with_single_map(CheckContext& ctx, CheckResult& result, const std::string& tag, const ParamSet& params,
                             const Features& hooks, const Bounds* view, const OrbitCamera* camera, float near_depth,
                             bool grade_interior) {
  BandSpec band = grading_band();
  band.fixed_screen_pixels = kBandPixels;
  const auto csm = ctx.measure(params, hooks, "lab12_" + tag + "_" + impl_name(ctx.impl), view, band, 960, 540, camera);
  Features single;  // lab 2's solution: the depth map fitted to the scene's box
  const auto one = ctx.measure(params, single, "lab12_" + tag + "_single_map", view, band, 960, 540, camera);
  ErrorPair whole{csm.metrics, one.metrics}, graded = whole;
  if (near_depth > 0.0f) {
    // The same pixels for both (the same camera and scene): those nearer than near_depth.
    const GBuffer g = ctx.renderer.read_gbuffer();
    const glm::mat4 camera_view = ctx.renderer.camera_view();
    Truth near_truth = csm.truth;
    for (std::size_t i = 0; i < near_truth.valid.size(); ++i)
      if (-(camera_view * glm::vec4(g.position[i], 1.0f)).z >= near_depth) near_truth.valid[i] = 0;
    graded = {compare(near_truth, csm.visibility), compare(near_truth, one.visibility)};
  }
  result.metrics[tag] = whole.to_json();
  std::printf("    %s: error (acne + leak, all pixels) cascades %.5f, single map %.5f (ratio %.3f)\n", tag.c_str(),
              ErrorPair::error(whole.cascades), ErrorPair::error(whole.single), whole.ratio());
  std::string graded_tag = tag;
  if (near_depth > 0.0f) {
    graded_tag = tag + "_near";
    result.metrics[graded_tag] = graded.to_json();
    result.metrics[graded_tag]["near_depth"] = near_depth;
    std::printf("    %s (view depth below %.2f): cascades %.5f, single map %.5f (ratio %.3f)\n", graded_tag.c_str(), near_depth,
                ErrorPair::error(graded.cascades), ErrorPair::error(graded.single), graded.ratio());
  }
  result.criteria.push_back({graded_tag + ".error_ratio_to_single_map", graded.ratio(), Criterion::kAtMost, kMaxErrorRatio,
                             "acne + leak at most 0.9 x lab 2's single map at the same texels",
                             "the cascades must spend their texels where the camera is: splits by the formula, each box "
                             "as small as its slice's sphere."});
  require_measurable(result, graded_tag, graded.cascades);
  if (grade_interior) grade_hard_shadow(result, tag + "_interior", whole.cascades, HardLimits{});
}

void check_cascades(CheckContext& ctx, CheckResult& result) {
  const CascadeFns fns = fns_for_file(ctx.graded.at(0));
  const bool compiled_in = ctx.graded.at(0) == kExercise || ctx.graded.at(0) == kSolution;
  const Features hooks = ctx.hooks();
  ParamSet params = ctx.params();
  params.set_from_string("shadow.map_size", std::to_string(kBudget));
  params.set("view.debug_quad", 0.0);
  params.set("csm.blend", 0.0);
  grade_splits(ctx, result, fns, compiled_in);
  grade_fit(ctx, result, fns);
  // The default scene (12 x 12 units) is small: a camera standing in it sees a frustum as wide as the
  // scene, so the far cascades are coarser than one map over the whole scene. Graded where the cascades
  // are meant to win, on the pixels of the first half of the cascades (view depth below the lab's split
  // C_N/2, from the formula); the whole view is reported.
  const OrbitCamera ground = ground_camera(ctx.scene().bounds());
  const int count = params.get(param::csm_count);
  const float near_depth = practical_splits(ground.near_plane, ground.far_plane, count,
                                            params.get(param::csm_lambda))[static_cast<std::size_t>((count + 1) / 2)];
  compare_with_single_map(ctx, result, "default_scene", params, hooks, nullptr, &ground, near_depth, true);
  grade_shimmer(ctx, result, params, hooks);
  // The PalmTree (10k triangles, a 392-unit sea): a camera standing on the island near the palms, its
  // far plane at the sea's edge (where cascades are meant to win: a view range far larger than what is
  // near the camera). Framed from outside, the island shows too few shadowed pixels to grade.
  const auto palm_path = data_dir() / kPalmTree;
  if (!std::filesystem::exists(palm_path)) throw std::runtime_error(palm_path.string() + ": model not found");
  ctx.use_scene(load_gltf(palm_path));
  const OrbitCamera palms = palm_camera(ctx.scene().bounds());
  ParamSet palm = params;
  palm.set("light.elevation", kPalmElevation);
  compare_with_single_map(ctx, result, "palm_tree", palm, hooks, nullptr, &palms, 0.0f, false);
  ctx.use_default_scene();
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Cascaded shadow maps";
  lab.summary = "Split the view range into cascades, one ortho box each: a sphere snapped to whole texels.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSpec bias = param::shadow_bias.spec(), slope = param::shadow_slope_bias.spec();
  bias.default_value = 0.00002;  // lab 2's: in depth units of the scene's extent along the light
  slope.default_value = 2.0;
  lab.params = csm_param_specs();
  lab.params.push_back(bias);
  lab.params.push_back(slope);
  lab.presets = {
      {"uniform", "lambda = 0: equal depth per cascade; the near cascade is as coarse as the far ones.", {{"csm.lambda", "0"}},
       {.provokes = "perspective aliasing", .fixed_by = "practical"}, {.camera = "eye=-4.5,0.8,4.5 target=-2.5,0,0 fov=50"}},
      {"logarithmic", "lambda = 1: equal far / near ratio; a tiny near cascade.", {{"csm.lambda", "1"}}},
      {"one cascade", "csm.count = 1: one map fitted to the view's slice of the scene.", {{"csm.count", "1"}},
       {.provokes = "perspective aliasing", .fixed_by = "practical"}, {.camera = "eye=-4.5,0.8,4.5 target=-2.5,0,0 fov=50"}},
      {"practical", "The lab's defaults: 4 cascades, lambda = 0.75 between uniform and logarithmic.",
       {{"csm.count", "4"}, {"csm.lambda", "0.75"}}},
      {"show cascades", "Each pixel tinted by its cascade.", {{"csm.show_cascades", "true"}}},
      {"blend", "A blend band over the last 20 % of each cascade.", {{"csm.blend", "0.2"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) { return hooks_for(fns_for_file(files.at(0))); };
  lab.check = check_cascades;
  for (int count : {2, 4})
    lab.bench.push_back({"csm " + std::to_string(count), "CSM", {{"csm.count", std::to_string(count)}}, true, true});
  return lab;
}

}  // namespace shadowlab
