// Lab 2: an orthographic light matrix fitted to the scene's bounding box (the course's task 2).
// Demonstrates: why the tutorials' fixed ortho box fails, the fit from centre and axes, and how the
// fit's tightness shows in shadow quality. Check: matrix properties over 10,006 directions, then error
// against the oracle on the default scene and the PalmTree model, fitted vs fixed.
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "labs/02_ortho_fit/ortho_fit.h"
#include "grading/check.h"
#include "grading/cpp_exercise.h"
#include "grading/lab.h"
#include "grading/light_view_answer.h"
#include "core/gltf_loader.h"

namespace shadowlab {

std::vector<glm::vec3> fit_test_directions(int random_directions) {
  std::vector<glm::vec3> dirs = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::mt19937 rng(2024);  // fixed seed: the same directions every run
  std::normal_distribution<float> gauss;
  while (static_cast<int>(dirs.size()) < random_directions + 6) {
    const glm::vec3 d(gauss(rng), gauss(rng), gauss(rng));
    if (glm::length(d) > 1e-3f) dirs.push_back(glm::normalize(d));
  }
  return dirs;
}

FitVerification verify_light_fit(const std::function<LightView(const Bounds&, const glm::vec3&)>& fit,
                                 const Bounds& bounds, int random_directions, double tolerance) {
  FitVerification v;
  for (const auto& d : fit_test_directions(random_directions)) {
    ++v.directions;
    const glm::mat4 m = fit(bounds, d).view_projection();
    bool finite = true;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) finite = finite && std::isfinite(m[c][r]);
    if (!finite) {
      ++v.non_finite;
      continue;
    }
    glm::dvec3 hi(-1e30), lo(1e30);
    for (int i = 0; i < 8; ++i) {
      const glm::dvec4 p = glm::dmat4(m) * glm::dvec4(glm::dvec3(bounds.corner(i)), 1.0);
      hi = glm::max(hi, glm::dvec3(p));
      lo = glm::min(lo, glm::dvec3(p));
    }
    double excess = -1e30, gap = -1e30;
    for (int a = 0; a < 3; ++a) {
      excess = std::max({excess, hi[a] - 1.0, -1.0 - lo[a]});
      gap = std::max({gap, 1.0 - hi[a], 1.0 + lo[a]});
    }
    // The image axes and world size against the matrix (see FitVerification).
    const LightView view = fit(bounds, d);
    const glm::dmat4 vp(m);
    const glm::dvec3 c(bounds.center());
    const glm::dvec3 x(view.image_x), y(view.image_y), dl(d);
    auto ndc_step = [&](const glm::dvec3& step) { return glm::dvec3(vp * glm::dvec4(c + step, 1.0) - vp * glm::dvec4(c, 1.0)); };
    const glm::dvec3 across_x = ndc_step(x * static_cast<double>(view.world_size.x));
    const glm::dvec3 across_y = ndc_step(y * static_cast<double>(view.world_size.y));
    const double kAxisTolerance = 1e-4;
    const bool axes_ok = std::abs(glm::length(x) - 1.0) < kAxisTolerance && std::abs(glm::length(y) - 1.0) < kAxisTolerance &&
                         std::abs(glm::dot(x, y)) < kAxisTolerance && std::abs(glm::dot(x, dl)) < kAxisTolerance &&
                         std::abs(glm::dot(y, dl)) < kAxisTolerance && std::abs(std::abs(across_x.x) - 2.0) < 1e-3 &&
                         std::abs(across_x.y) < 1e-3 && std::abs(std::abs(across_y.y) - 2.0) < 1e-3 && std::abs(across_y.x) < 1e-3;
    if (!axes_ok) ++v.inconsistent_axes;
    if (!(ndc_step(dl).z < 0.0)) ++v.depth_reversed;
    v.worst_excess = std::max(v.worst_excess, excess);
    v.worst_gap = std::max(v.worst_gap, gap);
    if (excess > tolerance) ++v.outside;
    if (gap > tolerance) ++v.loose;
  }
  return v;
}

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.cpp";
// The two fits have different texel sizes, so an edge band in texels would judge them on different
// pixels; a band of fixed width in screen pixels judges both on the same ones (as the benchmark does).
constexpr int kBandPixels = 2;
constexpr const char* kPalmTree = "assets/models/PalmTree/PalmTree.gltf";  // in the repository, with its licence
// Directions that may break a matrix property (NaN, a corner outside, a loose box, axes or depth): none.
constexpr double kMaxBadDirections = 0;
// Where the fixed box is wrong, the fit's error must be strictly below it (the stock exercise is the
// fixed box, so it cannot pass).
constexpr double kMaxErrorRatioToFixed = 0.999;
// The default scene moved off the origin (a box that ignores the scene's centre misses it).
constexpr float kMovedBy[] = {30.0f, 0.0f, 20.0f};

constexpr const char* kSolution = "core/light.cpp";  // fit_light_ortho, which every other lab uses

// A submission's exercise.cpp, built into its own program (grading/cpp_exercise.h) once per file and
// process (a check asks for the lab's hooks several times). Each fit is a call to it; answers asked
// for in advance (the test directions, in one exchange instead of 10,006 round trips) are kept.
class SubmittedFit {
 public:
  explicit SubmittedFit(const std::filesystem::path& file) : program_(spec(file)) {}

  LightView operator()(const Bounds& box, const glm::vec3& to_light) {
    const FitCall call = call_for(box, to_light);
    const auto found = answered_.find(key(call));
    return light_view_of(found != answered_.end() ? found->second : program_.call<FitAnswer>(call));
  }
  void prefetch(const Bounds& box, const std::vector<glm::vec3>& directions) {
    std::vector<FitCall> calls;
    for (const auto& d : directions) calls.push_back(call_for(box, d));
    const std::vector<FitAnswer> answers = program_.call_many<FitAnswer>(calls);
    for (std::size_t i = 0; i < calls.size(); ++i) answered_[key(calls[i])] = answers[i];
  }

 private:
  using Key = std::array<float, 9>;
  static CppExerciseSpec spec(const std::filesystem::path& file) {
    CppExerciseSpec spec;
    spec.source = file;
    spec.display_name = kExercise;
    spec.host = "02_ortho_fit";
    spec.headers = {"labs/02_ortho_fit/ortho_fit.h", "core/light.h", "core/scene.h"};
    spec.offered = {"shadowlab::orthonormal_basis", "shadowlab::fixed_tutorial_ortho",
                    "shadowlab::direction_from_angles", "shadowlab::clip_to_texture"};
    return spec;
  }
  static FitCall call_for(const Bounds& box, const glm::vec3& d) {
    return {{box.min.x, box.min.y, box.min.z}, {box.max.x, box.max.y, box.max.z}, {d.x, d.y, d.z}};
  }
  static Key key(const FitCall& c) {
    Key k;
    std::memcpy(k.data(), &c, sizeof k);
    return k;
  }
  CppExercise program_;
  std::map<Key, FitAnswer> answered_;
};
static_assert(sizeof(FitCall) == 9 * sizeof(float), "FitCall is the key: nine floats, no padding");

bool is_compiled_in(const std::filesystem::path& file) { return file == kExercise || file == kSolution; }

std::shared_ptr<SubmittedFit> submitted_fit(const std::filesystem::path& file) { return built_once<SubmittedFit>(file); }

// The fit in a slot: the exercise and the solution are compiled into the program (a student's own
// build: edit, rebuild, Check); any other file is a submission's, built on its own.
LightFit fit_for_file(const std::filesystem::path& file) {
  if (file == kExercise) return ortho_fit_exercise;
  if (file == kSolution) return fit_light_ortho;
  return [fit = submitted_fit(file)](const Bounds& box, const glm::vec3& to_light) { return (*fit)(box, to_light); };
}

// Error over all pixels, edges included (acne_rate_all + leak_rate_all), of the lab's fit and of the
// fixed tutorial box, on the current scene. Graded cases must be strictly lower than the fixed box's
// (so the stock exercise, which is the fixed box, cannot pass); reported cases are measured only.
void compare_with_fixed(CheckContext& ctx, CheckResult& result, const std::string& tag, const ParamSet& params,
                        const Bounds* view, bool graded) {
  Features fitted = ctx.hooks();
  Features fixed = fitted;
  fixed.light_fit = [](const Bounds&, const glm::vec3& to_light) { return fixed_tutorial_ortho(to_light); };
  BandSpec band = grading_band();
  band.fixed_screen_pixels = kBandPixels;
  const auto m_fit = ctx.measure(params, fitted, "lab02_" + tag + "_" + impl_name(ctx.impl), view, band);
  const auto m_fixed = ctx.measure(params, fixed, "lab02_" + tag + "_fixed", view, band);
  const double e_fit = m_fit.metrics.acne_rate_all + m_fit.metrics.leak_rate_all;
  const double e_fixed = m_fixed.metrics.acne_rate_all + m_fixed.metrics.leak_rate_all;
  result.metrics[tag] = {{"fitted", to_json(m_fit.metrics)}, {"fixed", to_json(m_fixed.metrics)},
                         {"error_fitted", e_fit}, {"error_fixed", e_fixed}, {"graded", graded}};
  if (graded)
    result.criteria.push_back({tag + ".error_ratio_fitted_to_fixed", e_fixed > 0 ? e_fit / e_fixed : 1.0,
                               Criterion::kAtMost, kMaxErrorRatioToFixed, "acne+leak (all pixels) below the fixed box's"});
}

void check_ortho_fit(CheckContext& ctx, CheckResult& result) {
  const LightFit fit = ctx.hooks().light_fit;
  // 1. Matrix properties over 10,006 directions, for the default scene's box and the PalmTree's.
  const auto palm_path = data_dir() / kPalmTree;
  if (!std::filesystem::exists(palm_path)) throw std::runtime_error(palm_path.string() + ": model not found");
  const Scene palm = load_gltf(palm_path);
  const std::pair<const char*, Bounds> boxes[] = {{"default_box", ctx.scene().bounds()}, {"palm_tree_box", palm.bounds()}};
  for (const auto& [tag_text, box] : boxes) {
    if (!is_compiled_in(ctx.graded.at(0))) submitted_fit(ctx.graded.at(0))->prefetch(box, fit_test_directions());
    const FitVerification v = verify_light_fit(fit, box);
    const std::string tag = tag_text;
    result.metrics[tag] = {{"directions", v.directions}, {"non_finite", v.non_finite}, {"outside", v.outside},
                           {"loose", v.loose}, {"worst_excess", v.worst_excess}, {"worst_gap", v.worst_gap},
                           {"inconsistent_axes", v.inconsistent_axes}, {"depth_reversed", v.depth_reversed}};
    result.criteria.push_back({tag + ".non_finite_directions", static_cast<double>(v.non_finite), Criterion::kAtMost, kMaxBadDirections,
                               "no NaN or Inf for any of 10,006 directions"});
    result.criteria.push_back({tag + ".corners_outside", static_cast<double>(v.outside), Criterion::kAtMost, kMaxBadDirections,
                               "every corner in [-1,1]^3 within 1e-5"});
    result.criteria.push_back({tag + ".loose_directions", static_cast<double>(v.loose), Criterion::kAtMost, kMaxBadDirections,
                               "the box touches both sides of every axis"});
    result.criteria.push_back({tag + ".inconsistent_axes", static_cast<double>(v.inconsistent_axes), Criterion::kAtMost, kMaxBadDirections,
                               "image_x, image_y unit and orthogonal to the light; world_size = the map's footprint",
                               "fill image_x = X, image_y = Y (the view's first two rows) and world_size = (2 hx, 2 hy): the "
                               "oracle and the bias read them."});
    result.criteria.push_back({tag + ".depth_reversed", static_cast<double>(v.depth_reversed), Criterion::kAtMost, kMaxBadDirections,
                               "a point nearer the light must get a smaller depth",
                               "Z must point toward the light (the view looks along -Z, as lookAt's does), so that near "
                               "and far are not swapped."});
  }
  // 2. Shadows against the oracle at a 1024^2 map, where the fixed box is wrong: the light straight down
  // (its lookAt degenerates), and the scene away from the origin (the box misses it).
  ParamSet params = ctx.params();
  params.set_from_string("shadow.map_size", "1024");
  params.set("view.debug_quad", 0.0);
  compare_with_fixed(ctx, result, "default_scene_lab_light", params, nullptr, false);
  params.set("light.elevation", 90.0);
  compare_with_fixed(ctx, result, "default_scene_straight_down", params, nullptr, true);
  params.set("light.elevation", ctx.params().get("light.elevation"));
  Scene moved = ctx.scene();
  for (auto& mesh : moved.meshes)
    transform_mesh(mesh, glm::translate(glm::mat4(1.0f), glm::vec3(kMovedBy[0], kMovedBy[1], kMovedBy[2])));
  ctx.use_scene(moved);
  compare_with_fixed(ctx, result, "default_scene_moved_30_20", params, nullptr, true);
  // PalmTree: small palms at the origin on a sea far wider. Straight down, the fixed box has no basis at
  // all. Under a low light the fixed box's +-10 units resolve the palms far more finely than a fit to the
  // whole sea, and the fit loses: reported, not graded (the recorded errors: docs/measured/lab_02.json,
  // quoted in the lab's INSTRUCTOR.md).
  ctx.use_scene(palm);
  params.set("light.elevation", 90.0);
  compare_with_fixed(ctx, result, "palm_tree_straight_down", params, nullptr, true);
  params.set("light.elevation", 10.0);
  const glm::vec3 to_light = direction_from_angles(params.get(param::light_azimuth), 10.0f);
  Bounds palms_and_shadow;
  for (const glm::vec3& corner : {glm::vec3(-2, 0, -2), glm::vec3(2, 0, 2), glm::vec3(-2, 3.9f, -2), glm::vec3(2, 3.9f, 2)}) {
    palms_and_shadow.extend(corner);
    palms_and_shadow.extend(corner - to_light * (corner.y / to_light.y));  // where its shadow meets the ground
  }
  compare_with_fixed(ctx, result, "palm_tree_low_light", params, &palms_and_shadow, false);
}

// The aliasing preset's view: 0.8 above the ground, close over the far corner of the big box's shadow
// under the default light, whose two edges run at a slant to the map's texel rows, so that the 256^2
// map's texels show as stairs up to 200 pixels long. Against "sharp" 3.49 % of a 1280x720 frame's pixels
// differ (cli.preset_contrast; from kShadowEdgeCamera, farther and higher, 1.33 %).
constexpr const char* kShadowCornerCamera = "eye=-4.6,0.8,1.1 target=-4.4,0,0.2 fov=30";

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Ortho light matrix fitted to the scene";
  lab.summary = "Replace the tutorials' fixed ortho box with one fitted to the bounding box, for any light direction.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  // Lab 1's lesson: a bias in texels, so the fitted and the fixed box are compared at the same bias in
  // world units (a constant in depth units would scale with each box's depth range).
  ParamSpec bias = param::shadow_bias.spec(), slope = param::shadow_slope_bias.spec();
  bias.default_value = 0.00002;
  slope.default_value = 2.0;
  lab.params = {bias, slope};
  lab.presets = {
      {"straight down", "The light along -Y: a lookAt with up = +Y has no basis here.", {{"light.elevation", "90"}}},
      {"grazing", "A low light: the box's footprint along the light grows long.", {{"light.elevation", "12"}}},
      {"aliasing", "A 256^2 map: blocky, jagged edges; a loose box wastes the few texels there are.", {{"shadow.map_size", "256"}},
       {.provokes = "aliasing", .fixed_by = "sharp"}, {.camera = kShadowCornerCamera}},
      {"sharp", "A 2048^2 map with the fitted box: fine edges.", {{"shadow.map_size", "2048"}}},
      {"far away", "The scene moved a million units along every axis: right with the local origin, broken without it.",
       {{"scene.offset_x", "-1e6"}, {"scene.offset_y", "1e6"}, {"scene.offset_z", "-1e6"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.light_fit = fit_for_file(files.at(0));
    return hooks;
  };
  lab.check = check_ortho_fit;
  return lab;
}

}  // namespace shadowlab
