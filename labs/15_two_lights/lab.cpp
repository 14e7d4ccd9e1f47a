// Lab 15: two shadowed lights, the sun and a flashlight (the Polish lab's ship with its reflector).
// Demonstrates: N lights in one frame, each with its own map and technique (the sun's ortho depth map, the
// flashlight's perspective one, core/flashlight.h), each light's Lambert term multiplied by its OWN shadow
// term; the flashlight's map redrawn alone while it moves. The student writes the flashlight's view and
// projection from the node that carries it (flashlight_view_exercise), with near and far fitted to the box.
// Check: 1. the matrices themselves, probed over nodes around four boxes (the scene's, scaled by 0.01 and
// by 100, moved), straight down and straight up included: finite, the view the node's rigid inverse, a
// perspective projection whose square image holds the cone exactly, near and far keeping every corner of
// the box and not loose. 2. The flashlight-alone frame (the sun's intensity 0) against the oracle's truth
// for the flashlight (Embree, rays cast toward it) times its Lambert term, on pixels in the interior of its
// truth, in four conditions: the lab's own node, held out from the seed (the node elsewhere on its circle,
// another cone and intensity), the node straight above the centre, and the flashlight on the camera.
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "labs/15_two_lights/flashlight_fit.h"
#include "grading/check.h"
#include "grading/cpp_exercise.h"
#include "grading/lab.h"
#include "grading/light_view_answer.h"
#include "core/flashlight.h"
#include "core/image_io.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.cpp";
constexpr const char* kSolution = "core/flashlight.cpp";  // flashlight_view, the renderer's default

// A pixel is wrong when its direct light differs from the truth's by more than this (the terms are 0 or
// 1 and the Lambert terms at least kGrazingNdotL where graded: a missing or extra light is >= 0.1 x its
// intensity; float rounding of n . l between the GPU and here is below 1e-5).
constexpr double kPixelTolerance = 0.02;
// At most this share of the graded pixels may be wrong in each frame (a right answer: 0; the maps'
// own misses in the interior, measured: see INSTRUCTOR.md).
constexpr double kMaxWrongShare = 0.005;
constexpr int kWidth = 640, kHeight = 360;

struct Condition {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> sets;
  float yaw = 30.0f;
};

struct Frame {
  const char* name;  // "sun", "flashlight", "combined"
  bool sun, flash;
};
// The flashlight alone (the sun's intensity 0): its shadows are the only ones the student's matrices make.
constexpr Frame kFrames[] = {{"flashlight", false, true}};

constexpr const char* kFrameAdvice =
    "the flashlight's shadows differ from the truth: its map must be seen from the node (its origin, along its "
    "-Z), hold the whole cone (fov twice the half-angle, aspect 1) and keep every caster between near and far; "
    "the probe.* rows say which.";

// What grade_condition counts on one frame's pixels, and its diff picture (red: brighter than the truth,
// blue: darker, grey: right).
struct PixelTally {
  long graded = 0, wrong = 0, sun_shadowed = 0, flash_shadowed = 0;
  double worst = 0.0;
  std::vector<std::uint8_t> diff = std::vector<std::uint8_t>(static_cast<std::size_t>(kWidth) * kHeight * 4, 0);
};

// The frame's direct light against the truth of both lights (`si`, `fi` their intensities), pixel by pixel.
PixelTally grade_pixels(const std::vector<float>& direct, const GBuffer& g, const FrameLight& f, const OracleLight& sun,
                        const Truth& ts, const Truth& tf, double si, double fi) {
  const float cos_rim_in = std::cos(glm::radians(f.spot_cone_deg - kSpotConeMarginDeg));
  const float cos_rim_out = std::cos(glm::radians(f.spot_cone_deg + kSpotConeMarginDeg));
  PixelTally t;
  long &graded = t.graded, &wrong = t.wrong, &sun_shadowed = t.sun_shadowed, &flash_shadowed = t.flash_shadowed;
  double& worst = t.worst;
  std::vector<std::uint8_t>& diff = t.diff;
  for (int i = 0; i < g.width * g.height; ++i) {
    if (!g.covered[i]) continue;
    const glm::vec3 n = g.normal[i];
    const float ns = glm::dot(n, sun.to_light);
    const glm::vec3 to_flash = glm::normalize(f.scene_position - g.position[i]);
    const float cos_axis = glm::dot(-to_flash, f.spot_direction);
    if (cos_axis < cos_rim_in && cos_axis > cos_rim_out) continue;  // the cone's rim: rounding decides
    const float nf = cos_axis >= cos_rim_in ? glm::dot(n, to_flash) : 0.0f;
    // Grazing light and the edge bands of either light's truth are not graded (as in every lab).
    if ((ns > 0.0f && ns < kGrazingNdotL) || (nf > 0.0f && nf < kGrazingNdotL)) continue;
    if ((ns > 0.0f && !ts.interior[i]) || (nf > 0.0f && !tf.interior[i])) continue;
    const double vs = ns > 0.0f && ts.lit[i] ? 1.0 : 0.0, vf = nf > 0.0f && tf.lit[i] ? 1.0 : 0.0;
    const double expected = si * std::max(ns, 0.0f) * vs + fi * std::max(nf, 0.0f) * vf;
    const double err = std::abs(static_cast<double>(direct[i]) - expected);
    ++graded;
    sun_shadowed += ns > 0.0f && !ts.lit[i];
    flash_shadowed += nf > 0.0f && !tf.lit[i];
    worst = std::max(worst, err);
    if (err > kPixelTolerance) {
      ++wrong;
      const int x = i % g.width, y = g.height - 1 - i / g.width;
      std::uint8_t* px = &diff[4 * (static_cast<std::size_t>(y) * kWidth + x)];
      px[0] = direct[i] > expected ? 255 : 0;
      px[2] = direct[i] > expected ? 0 : 255;
    }
    if (err <= kPixelTolerance) {
      const int x = i % g.width, y = g.height - 1 - i / g.width;
      std::uint8_t* px = &diff[4 * (static_cast<std::size_t>(y) * kWidth + x)];
      px[0] = px[1] = px[2] = static_cast<std::uint8_t>(std::min(255.0, 160.0 * expected + 40.0));
    }
    diff[4 * (static_cast<std::size_t>(g.height - 1 - i / g.width) * kWidth + i % g.width) + 3] = 255;
  }
  return t;
}

void grade_condition(CheckContext& ctx, CheckResult& result, const Features& hooks, const Condition& c) {
  ParamSet base = ctx.params();
  base.set("view.debug_quad", 0.0);
  for (const auto& [key, value] : c.sets) base.set_from_string(key, value);
  ctx.use(hooks);
  ctx.renderer.set_scene(ctx.scene());
  FrameRequest request;
  request.camera = OrbitCamera::framing(ctx.scene().bounds(), c.yaw, 35.0f);
  request.width = kWidth;
  request.height = kHeight;
  request.gbuffer = true;
  for (const Frame& frame : kFrames) {
    ParamSet p = base;
    if (!frame.sun) p.set("sun.intensity", 0.0);
    if (!frame.flash) p.set("flashlight.intensity", 0.0);
    ctx.renderer.render(p, request);
    const std::vector<float> direct = ctx.renderer.read_visibility();
    const GBuffer g = ctx.renderer.read_gbuffer();
    const ShadowedLight& flashlight = ctx.renderer.shadowed_light("flashlight");
    const FrameLight& f = flashlight.light();
    int map_size = 0;
    flashlight.read_depth(&map_size);
    OracleLight sun = oracle_light(ctx.renderer);
    OracleLight flash;
    flash.positional = true;
    flash.position = f.scene_position;
    flash.texel_angle = f.texel_angle(map_size);
    const Truth ts = ctx.oracle().evaluate(g, sun, grading_band());
    const Truth tf = ctx.oracle().evaluate(g, flash, grading_band());
    const double si = p.get("sun.intensity"), fi = p.get("flashlight.intensity");
    const PixelTally t = grade_pixels(direct, g, f, sun, ts, tf, si, fi);
    const long graded = t.graded, wrong = t.wrong, sun_shadowed = t.sun_shadowed, flash_shadowed = t.flash_shadowed;
    const double worst = t.worst;
    const std::vector<std::uint8_t>& diff = t.diff;
    const std::string tag = c.tag + "." + frame.name;
    const double share = graded > 0 ? static_cast<double>(wrong) / static_cast<double>(graded) : 1.0;
    result.metrics[c.tag][frame.name] = {{"graded_pixels", graded},    {"wrong_pixels", wrong},
                                         {"wrong_share", share},       {"worst_error", worst},
                                         {"sun_shadowed", sun_shadowed}, {"flashlight_shadowed", flash_shadowed}};
    result.criteria.push_back({tag + ".wrong_share", share, Criterion::kAtMost, kMaxWrongShare,
                               "at most 0.5 % of the graded pixels off the truth's direct light by more than 0.02",
                               kFrameAdvice});
    result.criteria.push_back({tag + ".graded_pixels", static_cast<double>(graded), Criterion::kAtLeast, kMinGradedPixels,
                               "enough pixels to grade"});
    if (!ctx.out_dir.empty()) {
      const std::string name = "lab15_" + c.tag + "_" + frame.name + "_" + impl_name(ctx.impl);
      const auto final_path = ctx.out_dir / (name + "_final.png");
      const auto diff_path = ctx.out_dir / (name + "_diff.png");
      write_png(final_path, kWidth, kHeight, ctx.renderer.read_color());
      write_png(diff_path, kWidth, kHeight, diff);
      ctx.images.push_back(final_path.string());
      ctx.images.push_back(diff_path.string());
    }
  }
}

// A submission's exercise.cpp, built into its own program (grading/cpp_exercise.h) once per file and
// process (a check asks for the lab's hooks several times). Each fit is a call to it.
class SubmittedFlashlight {
 public:
  explicit SubmittedFlashlight(const std::filesystem::path& file) : program_(spec(file)) {}
  LightView operator()(const glm::mat4& node, float cone_deg, const Bounds& box) {
    return light_view_of(program_.call<FlashlightAnswer>(call_for(node, cone_deg, box)));
  }
  std::vector<LightView> many(const std::vector<FlashlightCall>& calls) {
    std::vector<LightView> views;
    for (const FlashlightAnswer& a : program_.call_many<FlashlightAnswer>(calls)) views.push_back(light_view_of(a));
    return views;
  }
  static FlashlightCall call_for(const glm::mat4& node, float cone_deg, const Bounds& box) {
    FlashlightCall c{};
    std::memcpy(c.node_to_world, &node[0][0], sizeof c.node_to_world);
    for (int k = 0; k < 3; ++k) {
      c.box_min[k] = box.min[k];
      c.box_max[k] = box.max[k];
    }
    c.cone_deg = cone_deg;
    return c;
  }

 private:
  static CppExerciseSpec spec(const std::filesystem::path& file) {
    CppExerciseSpec spec;
    spec.source = file;
    spec.display_name = kExercise;
    spec.host = "15_two_lights";
    spec.headers = {"labs/15_two_lights/flashlight_fit.h", "core/light.h", "core/scene.h"};
    spec.offered = {"shadowlab::orthonormal_basis"};
    return spec;
  }
  CppExercise program_;
};

std::shared_ptr<SubmittedFlashlight> submitted_flashlight(const std::filesystem::path& file) {
  return built_once<SubmittedFlashlight>(file);
}

// The fit in the slot: the exercise and the solution are compiled into the program (a student's own
// build: edit, rebuild, Check); any other file is a submission's, built on its own.
FlashlightFit fit_for_file(const std::filesystem::path& file) {
  if (file == kExercise) return flashlight_view_exercise;
  if (file == kSolution) return flashlight_view;
  return [fit = submitted_flashlight(file)](const glm::mat4& node, float cone_deg, const Bounds& box) {
    return (*fit)(node, cone_deg, box);
  };
}

// 1. The probes: the matrices themselves, for nodes around four boxes.
struct ProbeCase {
  glm::mat4 node;
  float cone_deg;
  Bounds box;
};

// Cones cycled over the probes (half-angles in degrees, flashlight.cone_deg's range 5-60 and between).
constexpr float kProbeCones[] = {5.0f, 17.0f, 28.0f, 45.0f, 60.0f};
// The scene's box scaled about its centre by these, and moved by kProbeMove (a fixed near or far, or a
// view that ignores the node's position, cannot fit all four).
constexpr float kProbeScales[] = {1.0f, 0.01f, 100.0f};
constexpr float kProbeMove[] = {50.0f, 0.0f, -30.0f};
constexpr int kRandomNodesPerBox = 20;
constexpr int kProbePhaseStepDeg = 30;  // the lab's node around its circle

// A rigid node at `position` whose -Z is `direction`, turned by `roll_deg` about that axis.
glm::mat4 node_at(const glm::vec3& position, const glm::vec3& direction, float roll_deg) {
  const glm::mat3 axes = orthonormal_basis(-glm::normalize(direction));
  const glm::mat4 node(glm::vec4(axes[0], 0.0f), glm::vec4(axes[1], 0.0f), glm::vec4(axes[2], 0.0f), glm::vec4(position, 1.0f));
  return glm::rotate(node, glm::radians(roll_deg), glm::vec3(0.0f, 0.0f, 1.0f));
}

std::vector<ProbeCase> probe_cases(const Bounds& scene) {
  std::vector<Bounds> boxes;
  for (float scale : kProbeScales) {
    Bounds b;
    b.extend(scene.center() + scale * (scene.min - scene.center()));
    b.extend(scene.center() + scale * (scene.max - scene.center()));
    boxes.push_back(b);
  }
  Bounds moved = scene;
  moved.min += glm::vec3(kProbeMove[0], kProbeMove[1], kProbeMove[2]);
  moved.max += glm::vec3(kProbeMove[0], kProbeMove[1], kProbeMove[2]);
  boxes.push_back(moved);
  std::mt19937 rng(1515);  // fixed: the same probes every run
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss;
  std::vector<ProbeCase> cases;
  for (const Bounds& box : boxes) {
    const glm::vec3 c = box.center();
    const float h = 0.5f * glm::length(box.extent());
    auto add = [&](const glm::mat4& node) {
      cases.push_back({node, kProbeCones[cases.size() % std::size(kProbeCones)], box});
    };
    // The lab's node on its circle (flashlight_node_to_world, at the default radius and height), every
    // kProbePhaseStepDeg degrees, turned about its axis.
    ParamSet params(flashlight_param_specs());
    for (int phase = 0; phase < 360; phase += kProbePhaseStepDeg) {
      params.set("flashlight.phase", static_cast<double>(phase));
      add(glm::rotate(flashlight_node_to_world(params, box, glm::mat4(1.0f)), glm::radians(37.0f * phase), glm::vec3(0, 0, 1)));
    }
    add(node_at(c + glm::vec3(0.0f, 1.2f * h, 0.0f), {0.0f, -1.0f, 0.0f}, 0.0f));   // straight down
    add(node_at(c - glm::vec3(0.0f, 1.2f * h, 0.0f), {0.0f, 1.0f, 0.0f}, 20.0f));   // straight up
    add(node_at(c + 0.2f * h * glm::vec3(1.0f, 0.3f, -0.5f), {0.3f, -0.8f, 0.5f}, 0.0f));  // inside the box
    for (int i = 0; i < kRandomNodesPerBox; ++i) {
      glm::vec3 out(gauss(rng), gauss(rng), gauss(rng));
      out = glm::normalize(out + glm::vec3(0.0f, 1e-3f, 0.0f));
      const glm::vec3 position = c + (1.1f + 1.9f * unit(rng)) * h * out;
      const glm::vec3 aim = box.min + glm::vec3(unit(rng), unit(rng), unit(rng)) * box.extent();
      add(node_at(position, aim - position, 360.0f * unit(rng)));
    }
  }
  return cases;
}

// What the probes count: the cases where one property fails (each must be 0).
struct ProbeTally {
  int cases = 0, non_finite = 0, not_rigid = 0, off_node = 0, not_perspective = 0, cone_not_map = 0;
  int near_clips = 0, far_clips = 0, near_loose = 0, far_loose = 0;
};

// Calls where a property may fail: none.
constexpr double kMaxBadCalls = 0;
// Rounding allowed in the probes: the matrices are float, the probes' arithmetic double.
constexpr double kMatrixTolerance = 1e-4;
// The view's axis may also be off by this times the node's distance from the origin: a direction taken in
// float as (p + d) - p (what lookAt(p, p + d, up) does) loses about |p| x FLT_EPSILON / 2 of it.
constexpr double kPositionRounding = 4.0 * FLT_EPSILON;
// tan(cone) x the projection's x and y scales must be 1 within this (a fov of the cone itself: about 2).
constexpr double kConeTolerance = 1e-3;
// Near and far "fitted": at least this share of the fitted near, at most this many times the distance to
// the farthest corner (a fixed 0.1 or 1000 is off by more than 10 on the probes' scaled boxes).
constexpr double kMinNearShareOfFit = 0.5;
constexpr double kMaxFarOverFarthestCorner = 2.0;

void probe_one(const ProbeCase& pc, const LightView& v, ProbeTally& t) {
  ++t.cases;
  const glm::dmat4 view(v.view), proj(v.projection);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(view[c][r]) || !std::isfinite(proj[c][r])) {
        ++t.non_finite;
        return;
      }
  const glm::dvec3 position(pc.node[3]), axis = -glm::normalize(glm::dvec3(pc.node[2]));
  const double h = 0.5 * glm::length(glm::dvec3(pc.box.extent()));
  // The view: a rotation (orthonormal, determinant +1) and a translation, bottom row (0, 0, 0, 1)...
  const glm::dmat3 r(view);
  const glm::dmat3 rtr = glm::transpose(r) * r;
  double rigid_error = std::abs(glm::determinant(r) - 1.0);
  for (int c = 0; c < 3; ++c) {
    rigid_error = std::max(rigid_error, std::abs(view[c][3]));
    for (int k = 0; k < 3; ++k) rigid_error = std::max(rigid_error, std::abs(rtr[c][k] - (c == k ? 1.0 : 0.0)));
  }
  rigid_error = std::max(rigid_error, std::abs(view[3][3] - 1.0));
  if (rigid_error > kMatrixTolerance) ++t.not_rigid;
  // ... that puts the node's origin at the eye and its -Z on the view's -Z.
  const glm::dvec3 eye(view * glm::dvec4(position, 1.0));
  const glm::dvec3 looks(view * glm::dvec4(axis, 0.0));
  if (glm::length(eye) > kMatrixTolerance * std::max(h, glm::length(position)) ||
      glm::length(looks - glm::dvec3(0.0, 0.0, -1.0)) > kMatrixTolerance + kPositionRounding * glm::length(position))
    ++t.off_node;
  // The projection: perspective (w = -z in the eye's space), centred, square, the cone's rim on the
  // image's edges (tan(cone) x the x and y scales = 1).
  const bool perspective = std::abs(proj[2][3] + 1.0) < kMatrixTolerance && std::abs(proj[0][3]) < kMatrixTolerance &&
                           std::abs(proj[1][3]) < kMatrixTolerance && std::abs(proj[3][3]) < kMatrixTolerance;
  if (!perspective) {
    ++t.not_perspective;
    return;
  }
  const double tan_cone = std::tan(glm::radians(static_cast<double>(pc.cone_deg)));
  if (std::abs(proj[0][0] * tan_cone - 1.0) > kConeTolerance || std::abs(proj[1][1] * tan_cone - 1.0) > kConeTolerance ||
      std::abs(proj[2][0]) > kMatrixTolerance || std::abs(proj[2][1]) > kMatrixTolerance ||
      std::abs(proj[1][0]) > kMatrixTolerance || std::abs(proj[0][1]) > kMatrixTolerance)
    ++t.cone_not_map;
  // Near and far (GL's clip depth, back from the matrix) against the box's corners along the node's axis.
  const double near_plane = proj[3][2] / (proj[2][2] - 1.0), far_plane = proj[3][2] / (proj[2][2] + 1.0);
  double d_min = 1e300, d_max = -1e300, r_max = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 to_corner = glm::dvec3(pc.box.corner(i)) - position;
    d_min = std::min(d_min, glm::dot(to_corner, axis));
    d_max = std::max(d_max, glm::dot(to_corner, axis));
    r_max = std::max(r_max, glm::length(to_corner));
  }
  const double floor_ratio = kMaxFarOverNear;  // core/light.h: near is never below far / this
  if (!(near_plane <= std::max(d_min, far_plane / floor_ratio) * (1.0 + kMatrixTolerance))) ++t.near_clips;
  if (!(far_plane >= d_max * (1.0 - kMatrixTolerance))) ++t.far_clips;
  if (!(near_plane >= kMinNearShareOfFit * std::max(d_min, d_max / floor_ratio))) ++t.near_loose;
  if (!(far_plane <= kMaxFarOverFarthestCorner * r_max)) ++t.far_loose;
}

void probe_matrices(CheckContext& ctx, CheckResult& result) {
  const std::vector<ProbeCase> cases = probe_cases(ctx.scene().bounds());
  std::vector<LightView> views;
  const std::filesystem::path& file = ctx.graded.at(0);
  if (file == kExercise || file == kSolution) {
    const FlashlightFit fit = fit_for_file(file);
    for (const ProbeCase& pc : cases) views.push_back(fit(pc.node, pc.cone_deg, pc.box));
  } else {
    std::vector<FlashlightCall> calls;
    for (const ProbeCase& pc : cases) calls.push_back(SubmittedFlashlight::call_for(pc.node, pc.cone_deg, pc.box));
    views = submitted_flashlight(file)->many(calls);
  }
  ProbeTally t;
  for (std::size_t i = 0; i < cases.size(); ++i) probe_one(cases[i], views[i], t);
  result.metrics["probe"] = {{"cases", t.cases},           {"non_finite", t.non_finite},   {"view_not_rigid", t.not_rigid},
                             {"view_off_node", t.off_node}, {"not_perspective", t.not_perspective},
                             {"cone_not_map", t.cone_not_map}, {"near_clips", t.near_clips}, {"far_clips", t.far_clips},
                             {"near_loose", t.near_loose}, {"far_loose", t.far_loose}};
  auto row = [&](const char* name, int count, const char* why, const char* advice) {
    result.criteria.push_back({std::string("probe.") + name, static_cast<double>(count), Criterion::kAtMost, kMaxBadCalls, why, advice});
  };
  row("non_finite", t.non_finite, "no NaN or Inf in the view or the projection, for any node",
      "a lookAt whose up vector is parallel to the light has no basis (the node pointing straight down or up): take "
      "the node's own axes, or orthonormal_basis.");
  row("view_not_rigid", t.not_rigid, "the view is a rotation and a translation (bottom row 0, 0, 0, 1)",
      "the view is the inverse of the node's rigid transform: the rotation's transpose and -R^T p, in glm's "
      "column-major order (m[column][row]).");
  row("view_off_node", t.off_node, "the view puts the node's origin at the eye and the node's -Z on the view's -Z",
      "build the view from THIS call's node (its position node[3], its axis -node[2]), never from a fixed or "
      "remembered place, and do not return the node's transform itself (the view is its inverse).");
  row("not_perspective", t.not_perspective, "a perspective projection (w = -z in the light's eye space)",
      "a spot light spreads from a point: glm::perspective, not glm::ortho.");
  row("cone_not_map", t.cone_not_map, "the square map holds the cone exactly: fov twice the half-angle, aspect 1",
      "cone_deg is the HALF-angle: fovy = glm::radians(2 * cone_deg), aspect 1, centred on the axis.");
  row("near_clips", t.near_clips, "near at most the least depth of the box's corners (or far / 1000 where that is larger)",
      "near must not cut a caster: the least depth ALONG THE AXIS (dot(corner - p, axis)) of the 8 corners, not the "
      "distance to the box; never below far / kMaxFarOverNear.");
  row("far_clips", t.far_clips, "far at least the greatest depth of the box's corners",
      "far must keep the farthest receiver: the greatest depth along the axis of the 8 corners (or the distance "
      "to the farthest corner), never a number typed in.");
  row("near_loose", t.near_loose, "near at least half the fitted near (depth precision)",
      "fit near to the box (its least corner depth, floored at far / kMaxFarOverNear): a small fixed near spends "
      "the depth buffer's precision in front of the scene.");
  row("far_loose", t.far_loose, "far at most twice the distance to the farthest corner",
      "fit far to the box (its greatest corner depth or the farthest corner's distance), not a large fixed value.");
}

void check_two_lights(CheckContext& ctx, CheckResult& result) {
  probe_matrices(ctx, result);
  const Features hooks = ctx.hooks();
  std::vector<Condition> conditions = {{"node", {}, 30.0f}};
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  char text[64];
  Condition held{"held_out_node", {}, 30.0f + 60.0f * unit(rng)};
  std::snprintf(text, sizeof text, "%.1f", 150.0 + 100.0 * unit(rng));
  held.sets.push_back({"flashlight.phase", text});
  std::snprintf(text, sizeof text, "%.2f", 0.5 + 0.9 * unit(rng));
  held.sets.push_back({"flashlight.intensity", text});
  std::snprintf(text, sizeof text, "%.1f", 18.0 + 22.0 * unit(rng));
  held.sets.push_back({"flashlight.cone_deg", text});
  Condition down{"straight_down", {{"flashlight.radius", "0"}, {"flashlight.height", "1"}, {"flashlight.cone_deg", "40"}}, 30.0f};
  Condition camera{"held_out_camera", {{"flashlight.mount", "camera"}}, -40.0f - 50.0f * unit(rng)};
  for (Condition* c : {&held, &down, &camera}) {
    nlohmann::json sets = nlohmann::json::object();
    for (const auto& [k, v] : c->sets) sets[k] = v;
    result.conditions.push_back({{"tag", c->tag}, {"camera_yaw", c->yaw}, {"sets", sets}});
    conditions.push_back(*c);
  }
  for (const Condition& c : conditions) grade_condition(ctx, result, hooks, c);
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Two lights: the sun and a flashlight";
  lab.summary = "The flashlight's own shadow map follows its node: its view and perspective projection, near and far fitted to the box.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = flashlight_param_specs();
  // In the window a preset sets only its own keys over the current values (apply_preset), and Page Down
  // steps through these in order: each sets what its picture needs, the other light's intensity included.
  lab.presets = {
      {"moving node", "The node circles the scene: only the flashlight's map is drawn again (the panel's counters).",
       {{"flashlight.animate", "true"}, {"flashlight.mount", "node"}, {"flashlight.radius", "0.9"}, {"flashlight.height", "0.5"}}},
      {"flashlight on the camera", "The flashlight shines from the eye: orbit and watch its map follow.",
       {{"flashlight.mount", "camera"}, {"flashlight.animate", "false"}}},
      {"straight down", "The node right above the scene's centre, the flashlight pointing straight down.",
       {{"flashlight.mount", "node"}, {"flashlight.animate", "false"}, {"flashlight.radius", "0"}, {"flashlight.height", "1"}}},
      {"flashlight alone", "The sun off: only the flashlight's light and shadows.",
       {{"sun.intensity", "0"}, {"flashlight.intensity", "0.8"}}},
      {"sun alone", "The flashlight off: the one-light picture of the earlier labs.",
       {{"flashlight.intensity", "0"}, {"sun.intensity", "1"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.light = LightType::Directional;
    // The sun is the frame's light, the flashlight the list's one entry, placed with the slot's fit.
    hooks.lights = {flashlight_spec(fit_for_file(files.at(0)))};
    return hooks;
  };
  lab.check = check_two_lights;
  return lab;
}

}  // namespace shadowlab
