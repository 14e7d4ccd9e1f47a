// Grading a lab headless: render with the lab's exercise or solution, measure against the oracle, and
// compare each metric with its threshold. The same code runs from `shadowlab check` and the app's
// Check button.
#pragma once

#include <filesystem>
#include <functional>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grading/lab.h"
#include "oracle/metrics.h"
#include "oracle/oracle.h"
#include "renderer/renderer.h"

namespace shadowlab {

// One graded quantity: passes when `value <= limit` (or >= for kAtLeast).
struct Criterion {
  enum Direction { kAtMost, kAtLeast };
  std::string metric;
  double value = 0.0;
  Direction direction = kAtMost;
  double limit = 0.0;
  std::string why;     // where the limit comes from (for instructors: the JSON and the tooltip)
  std::string advice = {};  // what to change when it fails, in the student's terms; empty: the metric's usual advice
  // Where the limit comes from. On a scene that is not the lab's own (check --scene), a criterion the lab's
  // solution itself fails there is graded against the solution's own value on the same frames and truth
  // (kSolutionValue: the limit is that value with kAgainstSolutionMargin), and one the solution cannot be
  // measured on (too few graded pixels) is reported, not graded (kNotMeasurable).
  enum Basis { kLabLimit, kSolutionValue, kNotMeasurable };
  Basis basis = kLabLimit;
  bool passed() const {
    return basis == kNotMeasurable || (direction == kAtMost ? value <= limit : value >= limit);
  }
  // The measured fact as a sentence, followed by the advice when it failed: what the panel and the
  // command line print.
  std::string explain() const;
  // The same fact as one sentence for a student, its limit in the sentence's unit: "12.30 % of lit pixels
  // show acne (drawn in shadow); at most 0.2 % allowed (k3)." No advice (hint()), no metric name.
  std::string headline() const;
  // What to change: the lab's advice, else the metric's usual one; empty when that would only repeat the limit.
  std::string hint() const;
};

// How a lab's grading ended. CompileError: the student's file does not build (the same program builds
// with the solution's files); GraderError: the grader itself failed (its own shader, a missing asset,
// no GL context), which says nothing about the student.
// Crashed, TimedOut: a submitted C++ exercise, which runs in its own program (grading/cpp_exercise.h),
// crashed or did not return.
enum class CheckStatus { Passed, Failed, CompileError, GraderError, Crashed, TimedOut };
const char* status_name(CheckStatus status);

struct CheckResult {
  int lab = 0;
  std::string slug;
  Impl impl = Impl::Solution;
  std::string submission;  // the folder whose files were graded; empty: this tree's
  std::vector<Criterion> criteria;
  nlohmann::json metrics = nlohmann::json::object();  // everything measured, graded or not
  nlohmann::json parameters = nlohmann::json::object();  // the lab's parameters as graded (defaults + --set)
  nlohmann::json conditions = nlohmann::json::array();   // the held-out conditions drawn from the seed
  std::uint32_t seed = 0;
  std::vector<std::string> images;                   // files written under --out
  std::string error;                                 // a shader or setup failure fails the check
  bool students_error = false;                       // error is the student's (their file does not build)
  CheckStatus students_failure = CheckStatus::CompileError;  // with students_error: how their code failed
  std::string warnings;                              // compiler warnings in the graded files
  std::vector<std::string> notes;                    // what the student should know of how it was graded
  double seconds = 0.0;

  bool passed() const;
  CheckStatus status() const;
  // {"lab","slug","impl","status","passed","metrics","thresholds","criteria",...}
  nlohmann::json to_json() const;
};

// The band the checks grade with: 2 shadow-map texels around true shadow edges, and pixels the light
// grazes beyond 84 degrees (n . l < 0.1, where the taught slope bias stops growing: tan capped at 10).
inline constexpr float kGrazingNdotL = 0.1f;
inline BandSpec grading_band() {
  BandSpec band;
  band.grazing_n_dot_l = kGrazingNdotL;
  return band;
}

// The soft truth the checks grade a light with a size against (light.size > 0): evaluate_soft with
// 16 x 16 stratified samples of the light's disk per pixel. Its own error, measured against closed forms
// by tests/test_soft_truth.cpp (the disk's circular segment behind a straight edge): mean 0.0031, worst
// single pixel 0.019 -- an order below the penumbra limit graded with (kPenumbraErrorLimit).
inline constexpr int kSoftTruthStrata = 16;
inline constexpr double kSoftTruthMeanError = 0.0031;
inline constexpr double kSoftTruthWorstError = 0.019;

// What a lab's check gets: a renderer in a headless context, the scene, the oracle for it, and the files
// being graded.
class CheckContext {
 public:
  CheckContext(Renderer& renderer, const Lab& lab, Impl impl, const Scene& default_scene, std::filesystem::path out_dir);

  Renderer& renderer;
  const Lab& lab;
  Impl impl;
  std::filesystem::path out_dir;  // empty: write no images
  // The files in the lab's exercise slots: lab.files(impl), or a submission's (see grade_submission).
  SlotFiles graded;
  // The submission's folder (grade_submission); empty: this tree's files are graded.
  std::filesystem::path submission;
  // Held-out conditions (light directions, map sizes, ...) are drawn from this seed and recorded.
  std::uint32_t seed = kDefaultSeed;
  static constexpr std::uint32_t kDefaultSeed = 1;

  // Grade a submission: a folder laid out like the project, whose files take the exercise's slots.
  void grade_submission(const std::filesystem::path& folder);
  // Grade the lab's own C++ exercise files from disk where they differ from the copies compiled into this
  // program (Lab::compiled_copies): each such slot then holds the file's absolute path, which the lab
  // builds on its own like a submission's. Returns a note per file so graded; throws ExerciseError where
  // this platform cannot build a file on its own (no sandbox: rebuild instead).
  std::vector<std::string> grade_edited_cpp_files();

  // The graded files' hooks; and the solution's hooks with only slot `slot` taken from the graded
  // files (to grade one part of a multi-file exercise on its own).
  Features hooks() const { return lab.hooks_for(graded); }
  Features hooks_with_only(std::size_t slot) const;
  // Builds the hooks' programs or throws BuildError with the compiler's messages.
  void use(const Features& hooks);

  // The scene to grade on (--scene, or the lab's own choice of built-in scene).
  const Scene& scene() const { return *scene_; }
  void use_scene(const Scene& scene);
  void use_default_scene();  // back to --scene or the built-in default
  // A named scene for held-out conditions: "default" (as use_default_scene) or "stacked" (occluders at
  // three heights over a receiver).
  void use_scene_named(const std::string& name);
  // A random engine for held-out conditions, from the seed and the lab's number.
  std::mt19937 held_out_rng() const { return std::mt19937(seed * 1000003u + static_cast<std::uint32_t>(lab.number)); }
  const Oracle& oracle();
  // The lab's parameters with the command line's --set values applied.
  ParamSet params() const;
  std::vector<std::string> assignments;

  struct Measurement {
    Metrics metrics;
    // With light.size > 0, the hard truth softened (metrics.h's soften: the penumbra joins the edge
    // band) and metrics with the penumbra figures (Metrics::soft) against `soft`, the visible fractions.
    Truth truth;
    SoftTruth soft;
    std::vector<float> visibility;
    double render_ms = 0.0;
    double oracle_ms = 0.0;
  };
  // Renders the current scene with these parameters and hooks, grades it against the oracle and, when
  // out_dir is set, writes `<name>_final.png` and `<name>_diff.png`.
  // The camera frames `view` (default: the whole scene's bounds).
  // A spot light lights only its cone: pixels outside it (and within kSpotConeMarginDeg of its rim, where
  // the shader's and this test's rounding may differ) are not graded. `camera` replaces the framing.
  // `truth_oracle` replaces the scene's oracle (casters the scene does not hold, e.g. lab 11's
  // billboards as the light should see them); its truth is not reused by later measurements.
  Measurement measure(const ParamSet& params, const Features& hooks, const std::string& name,
                      const Bounds* view = nullptr, const BandSpec& band = grading_band(), int width = 960, int height = 540,
                      const OrbitCamera* camera = nullptr, const Oracle* truth_oracle = nullptr);

  std::vector<std::string> images;

 private:
  const Scene* default_scene_;
  const Scene* scene_;
  int scene_generation_ = 0;     // bumped by every use_scene*
  int uploaded_generation_ = -1;  // the generation the renderer holds now
  std::unique_ptr<Scene> owned_scene_;
  std::unique_ptr<Oracle> oracle_;
  // The last truth and what it was computed from: a measurement that sees the same pixels under the same
  // light (a sweep of a shading parameter) reuses it instead of casting every ray again.
  struct LastTruth {
    int scene_generation = -1;
    GBuffer gbuffer;
    OracleLight light;
    BandSpec band;
    Truth truth;
    float size = 0.0f;
    SoftTruth soft;
  };
  LastTruth last_;
};

// The least number of interior lit and of interior shadowed pixels a measurement must see to grade
// anything: below it a check fails as "not measurable" (a scene with nothing to shadow, a degenerate
// triangle) rather than pass on no evidence. At 960 x 540 the labs' scenes give 20,000-300,000 of each.
inline constexpr double kMinGradedPixels = 500;

// The mean error allowed over the penumbra of a sized light (the soft truth's own mean error is 0.0031,
// its worst pixel 0.019). Measured: see INSTRUCTOR notes of the soft-shadow lab and test_check_soft.
inline constexpr double kPenumbraErrorLimit = 0.05;

// The limits of a hard (0 or 1) shadow against the truth, over interior pixels: the continuous errors
// (mean darkening of lit pixels, mean light in shadowed ones), so a partly darkened answer fails too.
struct HardLimits {
  double lit_error = 0.001;     // acne: 0.1 % of the lit interior, or darkening of 0.001 on average
  double shadow_error = 0.005;  // leak: 0.5 % of the shadowed interior
  std::string why = "lab 1's bounds: 0.1 % acne, 0.5 % leak, interior pixels";
  // What the student should change when each fails (empty: the metric's usual advice).
  std::string lit_advice = {};
  std::string shadow_advice = {};
  // Only with a sized light (Metrics::soft): the mean |visibility - visible fraction| over the penumbra.
  double penumbra_error = kPenumbraErrorLimit;
  std::string penumbra_advice = {};
};
// Adds `<tag>.lit_error`, `<tag>.shadow_error` and `<tag>.graded_pixels` (not measurable below
// kMinGradedPixels) to the result, and the measurement's metrics under result.metrics[tag]. Against a
// sized light (m.soft) the interior is the fully lit region and the umbra, and `<tag>.penumbra_error`
// grades the penumbra.
void grade_hard_shadow(CheckResult& result, const std::string& tag, const Metrics& m, const HardLimits& limits = {});
// Where the penumbra limit comes from, for a criterion's `why`.
std::string soft_truth_why(double limit);
// Only the "not measurable" criterion, for measurements graded otherwise.
void require_measurable(CheckResult& result, const std::string& tag, const Metrics& m);

// The region where the occluders' shadows fall on the receiver (y = 0) of the stacked-occluder scene,
// so the camera spends its pixels on the overlaps where light bleeding happens rather than on open
// ground (labs 4 and 13).
Bounds shadows_on_receiver(const Scene& scene, const glm::vec3& to_light);

// The default scene and the same light at a grazing elevation (10 deg), each graded as a hard shadow
// (grade_hard_shadow, lab 1's bounds, tags "default" and "grazing"): for soft techniques that must still
// shade an ordinary scene right (labs 13, 14). Pictures are named `<prefix>_<tag>_<impl>`.
void grade_default_and_grazing(CheckContext& ctx, CheckResult& result, const ParamSet& params, const Features& hooks,
                               const std::string& prefix);

// A held-out condition for a directional light: a scene, a light direction and a map size the lab's
// text does not fix, drawn from the seed and recorded in the result's "conditions".
struct DirectionalCase {
  std::string tag;    // "held_out_1", ...
  std::string scene;  // "default" or "stacked" (see CheckContext::use_scene_named)
  float azimuth = 0.0f, elevation = 45.0f;
  std::string map_size;  // a shadow.map_size choice
  nlohmann::json to_json() const;
  // The parameters with this case's light and map size (and the case's scene made current in ctx).
  ParamSet apply(CheckContext& ctx, const ParamSet& params) const;
};

// Where one held-out case is drawn from: an elevation range, map sizes and scenes to pick from.
struct HeldOutRange {
  float min_elevation = 0.0f, max_elevation = 90.0f;
  std::vector<std::string> map_sizes;
  std::vector<std::string> scenes;
};
// One case per range (so low and high lights are always both there), azimuth within 75 degrees of the
// lab's, the rest picked from the range's lists, all drawn from the seed.
std::vector<DirectionalCase> draw_directional_cases(CheckContext& ctx, const std::vector<HeldOutRange>& ranges);
// Grades a hard shadow at the lab's own light (`params`, as `tag`, with its render and oracle times), then
// at the held-out directional cases drawn from `ranges` (`held_out_params` with each case's light, map
// size and scene), recording each case in result.conditions; images are named `<prefix>_<tag>_<impl>`.
// Leaves the default scene in use.
void grade_lab_and_held_out_lights(CheckContext& ctx, CheckResult& result, const std::string& prefix,
                                   const std::string& tag, const ParamSet& params, const ParamSet& held_out_params,
                                   const std::vector<HeldOutRange>& ranges, const HardLimits& limits);

// On a scene not the lab's own, how much worse than the lab's solution an answer may be where the solution
// fails the lab's limit: the solution's value times 1 + this (an error), or times 1 - this (an agreement).
inline constexpr double kAgainstSolutionMargin = 0.1;
// Regrades `result` against `solution`, the lab's solution graded on the same scene, seed and settings:
// each criterion the solution fails gets the solution's value (with the margin) as its limit, or is not
// measurable when the solution fails it for too few graded pixels or measures 0 of what an at-least
// criterion needs (no camera inside a volume, no shadowed quarter); a note says so.
void grade_against_solution(CheckResult& result, const CheckResult& solution);

// A scene not the lab's own is graded in the lab's frame: every length a lab's conditions give in absolute
// units (spot and point light positions, a positional light's size, cameras and their eyes, boxes, a bias a
// shader applies in world units) was chosen on the lab's own scene, and would stand nowhere useful on a model
// a thousand times smaller or far from the origin. The foreign scene is moved and scaled instead (a
// similarity, in double: one scale about the centre of its box, then a move), so that its bounding sphere
// (centre of the box, half its diagonal, with the ground plane the renderer adds to it) is the lab's scene's:
// lengths are in units of the scene's bounding radius about its centre. What is graded (fractions of pixels,
// visibility, angles) does not change under a similarity; a scaled and moved copy of the lab's scene grades
// as the lab's scene does.
struct LabFrame {
  double scale = 1.0;            // lab units per scene unit
  glm::dvec3 from{0.0};          // the centre of the scene's box, in its own frame
  glm::dvec3 to{0.0};            // the centre of the lab's scene's box
  glm::vec3 apply(const glm::vec3& p) const { return glm::vec3(to + scale * (glm::dvec3(p) - from)); }
};
// The similarity that puts `scene`'s bounding sphere on `lab`'s (the identity when either is empty; a move
// only when `scene` is a point).
LabFrame lab_frame(const Bounds& scene, const Bounds& lab);
// The scene with every position mapped (normals unchanged: the scale is uniform and positive) and its origin
// at the lab's (the positions are the lab frame's own).
Scene in_lab_frame(const Scene& scene, const LabFrame& frame);

// One lab's grading as `shadowlab check` and the window's Check button run it.
struct CheckRun {
  Impl impl = Impl::Exercise;
  std::filesystem::path submission;  // non-empty: grade this folder's exercise files
  std::uint32_t seed = CheckContext::kDefaultSeed;
  std::vector<std::string> assignments;  // --set key=value over the lab's defaults
  std::filesystem::path out_dir;         // empty: no images
  // The scene is not the lab's own (check --scene): it is graded in the lab's frame (LabFrame), and as its
  // limits were measured on the built-in scenes, the answer is also graded against the solution's own results
  // there (grade_against_solution).
  bool foreign_scene = false;
};

// Grades one lab; never throws: a failure of any kind ends up in the result (error, students_error).
CheckResult run_lab_check(Renderer& renderer, const Lab& lab, const Scene& scene, const CheckRun& run);

// The oracle's view of the renderer's light for the last frame: directional, or positional (spot and
// point lights) with the angle one shadow-map texel spans for the edge band.
OracleLight oracle_light(const Renderer& renderer);

inline constexpr float kSpotConeMarginDeg = 1.0f;

// The share of graded interior (non-edge) pixels whose lit/shadowed answer agrees with the oracle.
double interior_agreement(const Metrics& m);

// An orbit camera at `eye` looking at `target` (for views from a chosen place, e.g. inside a volume).
OrbitCamera camera_looking_at(const glm::vec3& eye, const glm::vec3& target, float near_plane, float far_plane);

}  // namespace shadowlab
