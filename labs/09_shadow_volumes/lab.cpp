// Lab 9: stencil shadow volumes (lecture 9).
// Demonstrates: silhouette edges found per triangle in a geometry shader from GL_TRIANGLES_ADJACENCY,
// side quads extruded to infinity (w = 0) under a projection with its far plane at infinity, z-pass
// and z-fail (Carmack's reverse) counting in a two-sided stencil pass, the ambient / stencil / additive
// lit passes, and the adjacency report of open and non-manifold edges. The student writes what a
// triangle emits: silhouette sides and both caps. Check: agreement with the oracle on non-edge pixels
// for a directional and a point light, z-pass from outside (the sides alone) and z-fail (closed
// volumes), a held-out light, and the camera inside a shadow volume, where z-fail must stay right and
// z-pass is shown failing; the volumes' triangle count against the solution's (each silhouette once).
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "labs/09_shadow_volumes/gl_volume_setup.h"
#include "grading/check.h"
#include "grading/gl_exercise_check.h"
#include "grading/lab.h"
#include "renderer/shadow_volume_pass.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/volume/volume.glsl";  // the renderer's own volumes

// The target: shadow volumes are exact hard shadows, so they must agree with the ray-cast truth
// on at least 99.5 % of the pixels away from shadow edges.
constexpr double kMinAgreement = 0.995;
// Shadow volumes have no texels: the edge band is the pixels whose truth changes within this many screen
// pixels (rasterisation and ray casting may differ by a pixel along an edge).
constexpr int kBandPixels = 1;
// z-pass with the camera inside a volume must fail visibly: at least this share of the graded pixels
// wrong. The eye is inside exactly one volume, so every count is off by one and the picture inverts
// (measured error: labs/09_shadow_volumes/INSTRUCTOR.md).
constexpr double kMinZPassInsideError = 0.05;
// Silhouette extrusion: the volumes may hold no more side triangles (quads swept by edges) than the
// solution's: each silhouette edge once. Extruding every edge of every lit triangle gives the same shadows
// with several times the sides (and fill); how a student caps the volumes is graded by the images.
// An open edge (one triangle only) is a silhouette whichever way its triangle faces, so an answer that
// extrudes from the unlit side (the corpus's right extruded_from_unlit_side) draws it when the solution
// does not: each open edge may add one quad (two triangles) to the limit. On the lab's scene only the
// ground's 4 edges are open; on a model with holes (Suzanne's eyes) they decide.
constexpr double kMaxSidesRatio = 1.0;

// The held-out suns' elevation bands (degrees), one sun drawn in each, so that every seed grades a low
// sun: its shadows are 3.5 to 7 times as long as their casters are high, and a volume that stops short of
// infinity ends inside them (the corpus's extruded_finite_distance). The lowest band starts where the
// solution was measured to pass at every azimuth the draw allows (INSTRUCTOR.md).
struct HeldOutSun {
  const char* name;  // the tag is held_out_<name>zfail
  float min_elevation, max_elevation;
};
constexpr HeldOutSun kHeldOutSuns[] = {{"", 16.0f, 80.0f}, {"low_", 8.0f, 16.0f}};

// Inside the big box's shadow (light at azimuth 35, elevation 50): a point 0.3 above the ground just
// beyond the box, looking away from it across the shadow it casts.
const glm::vec3 kInsideEye{-3.67f, 0.3f, -0.68f};
const glm::vec3 kInsideTarget{-3.5f, 0.0f, 4.0f};

void report_adjacency(CheckContext& ctx, CheckResult& result) {
  nlohmann::json meshes = nlohmann::json::array();
  for (const auto& m : ctx.renderer.volume_report()) {
    meshes.push_back({{"mesh", m.name},
                      {"triangles", m.triangles},
                      {"edges", m.edges},
                      {"open_edges", m.open_edges},
                      {"non_manifold_edges", m.non_manifold_edges},
                      {"inconsistent_edges", m.inconsistent_edges}});
    if (!m.closed_manifold())
      std::printf("    adjacency: %s has %zu open, %zu non-manifold, %zu inconsistent edges (treated as silhouettes)\n",
                  m.name.c_str(), m.open_edges, m.non_manifold_edges, m.inconsistent_edges);
  }
  result.metrics["adjacency"] = meshes;
}

const char* kSidesAdvice =
    "extrude each silhouette edge (between a triangle facing the light and a neighbour facing away) once, into a "
    "quad to infinity, counter-clockwise seen from outside the volume (in the order the lit triangle runs the edge).";
const char* kCapsAdvice =
    "with u_caps (z-fail) close each volume: the lit triangle itself as the near cap and the same triangle at "
    "infinity, in reversed order, as the far cap (both facing out of the volume).";

void grade(CheckResult& result, const std::string& tag, const CheckContext::Measurement& m, bool graded,
           const char* advice = kCapsAdvice) {
  const double agreement = interior_agreement(m.metrics);
  result.metrics[tag] = to_json(m.metrics);
  result.metrics[tag]["interior_agreement"] = agreement;
  std::printf("    %-22s agreement %.5f  (acne %.5f, leak %.5f, %llu interior px)\n", tag.c_str(), agreement,
              m.metrics.acne_rate, m.metrics.leak_rate,
              static_cast<unsigned long long>(m.metrics.interior_lit + m.metrics.interior_shadowed));
  if (graded) {
    result.criteria.push_back({tag + ".interior_agreement", agreement, Criterion::kAtLeast, kMinAgreement,
                               "exact hard shadows: >= 99.5 % of non-edge pixels", advice});
    require_measurable(result, tag, m.metrics);
  }
}

// The triangles the solution's volumes hold for the current scene and light.
VolumeTriangles solution_triangles(CheckContext& ctx, const ParamSet& params, bool caps) {
  ctx.use(ctx.lab.hooks(Impl::Solution));
  FrameRequest request;
  request.camera = OrbitCamera::framing(ctx.scene().bounds());
  request.width = 64;
  request.height = 64;
  ctx.renderer.render(params, request);
  return ctx.renderer.count_volume_triangles(caps);
}

double ratio(long graded, long reference) {
  return reference > 0 ? static_cast<double>(graded) / static_cast<double>(reference) : 0.0;
}

// Lab 9's GL exercise (gl_volume_setup.h): the graded gl_volume_stencil.cpp (the file on disk, a
// submission's, or the solution: the renderer's renderer/volume_stencil.cpp) is built with its host and
// run in the sandbox, once per counting method.
constexpr const char* kGlExercise = SHADOWLAB_LAB_FOLDER "/gl_volume_stencil.cpp";
constexpr const char* kGlSolution = "renderer/volume_stencil.cpp";
// State is exact: no wrong column, setting or error is allowed.
constexpr double kNoDifference = 0;
// A column's red channel may differ from ambient (+ light) by one step of its 8 bits (the blend's rounding).
constexpr int kRedTolerance = 1;
constexpr int kStencilRange = 256;  // the 8 bits of GL_DEPTH24_STENCIL8

std::string gl_name(int value) {
  static const std::map<int, std::string> names = {
      {GL_NO_ERROR, "GL_NO_ERROR"}, {GL_KEEP, "GL_KEEP"}, {GL_ZERO, "GL_ZERO"}, {GL_REPLACE, "GL_REPLACE"},
      {GL_INCR, "GL_INCR"}, {GL_DECR, "GL_DECR"}, {GL_INCR_WRAP, "GL_INCR_WRAP"}, {GL_DECR_WRAP, "GL_DECR_WRAP"},
      {GL_INVERT, "GL_INVERT"}, {GL_NEVER, "GL_NEVER"}, {GL_LESS, "GL_LESS"}, {GL_EQUAL, "GL_EQUAL"},
      {GL_LEQUAL, "GL_LEQUAL"}, {GL_GREATER, "GL_GREATER"}, {GL_NOTEQUAL, "GL_NOTEQUAL"}, {GL_GEQUAL, "GL_GEQUAL"},
      {GL_ALWAYS, "GL_ALWAYS"}, {GL_SRC_ALPHA, "GL_SRC_ALPHA"}, {GL_ONE_MINUS_SRC_ALPHA, "GL_ONE_MINUS_SRC_ALPHA"},
      {GL_INVALID_ENUM, "GL_INVALID_ENUM"}, {GL_INVALID_VALUE, "GL_INVALID_VALUE"},
      {GL_INVALID_OPERATION, "GL_INVALID_OPERATION"}};
  const auto found = names.find(value);
  return found != names.end() ? found->second : std::to_string(value);
}

nlohmann::json pass_json(const VolumeState& s) {
  auto names = [](const int* v, int n) {
    nlohmann::json a = nlohmann::json::array();
    for (int i = 0; i < n; ++i) a.push_back(gl_name(v[i]));
    return a;
  };
  return {{"gl_error_after_pass", gl_name(s.gl_error_after_pass)}, {"draws", s.draws},
          {"stencil_test", s.stencil_test != 0}, {"stencil_func", gl_name(s.stencil_func)}, {"stencil_ref", s.stencil_ref},
          {"stencil_value_mask", s.stencil_value_mask}, {"stencil_writemask", s.stencil_writemask},
          {"front_ops", names(s.front_ops, 3)}, {"back_ops", names(s.back_ops, 3)},
          {"colour_writemask", {s.colour_writemask[0], s.colour_writemask[1], s.colour_writemask[2], s.colour_writemask[3]}},
          {"depth_writemask", s.depth_writemask != 0}, {"depth_test", s.depth_test != 0},
          {"depth_func", gl_name(s.depth_func)}, {"depth_clamp", s.depth_clamp != 0}, {"cull_face", s.cull_face != 0},
          {"stencil_at_first_draw", s.stencil_at_first_draw},
          {"counts", std::vector<int>(std::begin(s.counts), std::end(s.counts))},
          {"red", std::vector<int>(std::begin(s.red), std::end(s.red))}};
}

nlohmann::json lit_json(const VolumeState& s) {
  return {{"gl_error_after_lit", gl_name(s.gl_error_after_lit)}, {"stencil_test", s.lit_stencil_test != 0},
          {"stencil_func", gl_name(s.lit_stencil_func)}, {"stencil_ref", s.lit_stencil_ref},
          {"stencil_value_mask", s.lit_stencil_value_mask}, {"depth_test", s.lit_depth_test != 0},
          {"depth_func", gl_name(s.lit_depth_func)}, {"depth_writemask", s.lit_depth_writemask != 0},
          {"blend", s.blend != 0}, {"blend_src_rgb", gl_name(s.blend_src_rgb)}, {"blend_dst_rgb", gl_name(s.blend_dst_rgb)}};
}

// Whether the stencil test (func, ref, mask) passes a stored value, as the OpenGL 3.3 core profile
// specification defines it (section 4.1.4, Stencil Test).
bool stencil_passes(int func, int ref, int mask, int stored) {
  const int r = ref & mask, s = stored & mask;
  switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return r < s;
    case GL_LEQUAL: return r <= s;
    case GL_GREATER: return r > s;
    case GL_GEQUAL: return r >= s;
    case GL_EQUAL: return r == s;
    case GL_NOTEQUAL: return r != s;
    default: return true;
  }
}

// The stored counts the lit test gets wrong: it must pass 0 (lit) and no other count (inside a volume).
double lit_test_wrong_counts(const VolumeState& s) {
  if (!s.lit_stencil_test) return kStencilRange - 1;
  double wrong = 0;
  for (int stored = 0; stored < kStencilRange; ++stored)
    wrong += stencil_passes(s.lit_stencil_func, s.lit_stencil_ref, s.lit_stencil_value_mask, stored) != (stored == 0);
  return wrong;
}

void add_pass_criteria(const VolumeState& s, bool z_fail, CheckResult& result) {
  auto& c = result.criteria;
  const std::string p = std::string("gl_stencil.") + (z_fail ? "zfail" : "zpass") + ".";
  const std::string read = std::string("read back with glGet* when stencil_pass(") + (z_fail ? "true" : "false") +
                           ") first calls draw_volumes (an OpenGL state, not a tolerance)";
  c.push_back({p + "volumes_not_drawn", s.draws > 0 ? 0.0 : 1.0, Criterion::kAtMost, kNoDifference,
               "calls of draw_volumes", "call draw_volumes() once the state is set: it draws every volume."});
  c.push_back({p + "stencil_not_cleared", s.stencil_at_first_draw == 0 ? 0.0 : 1.0, Criterion::kAtMost, kNoDifference,
               "the stencil when draw_volumes is first called; the host left 3 there (a last frame's counts)",
               "clear the stencil to 0 first (glStencilMask(0xFF), glClearStencil(0), glClear(GL_STENCIL_BUFFER_BIT)): "
               "otherwise last frame's counts are added to and no pixel is 0."});
  const double colour = s.colour_writemask[0] + s.colour_writemask[1] + s.colour_writemask[2] + s.colour_writemask[3];
  c.push_back({p + "colour_writes_on", colour, Criterion::kAtMost, kNoDifference, read + ": GL_COLOR_WRITEMASK",
               "glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE) before drawing the volumes: they are counted, not "
               "seen; with colour on they paint over the ambient picture."});
  c.push_back({p + "depth_writes_on", static_cast<double>(s.depth_writemask != 0), Criterion::kAtMost, kNoDifference,
               read + ": GL_DEPTH_WRITEMASK",
               "glDepthMask(GL_FALSE): a volume face that writes its depth hides the surface behind it from the other "
               "faces and from the lit pass's equal-depth test."});
  const bool depth_ok = s.depth_test && (s.depth_func == GL_LESS || s.depth_func == GL_LEQUAL);
  c.push_back({p + "depth_test_not_less", depth_ok ? 0.0 : 1.0, Criterion::kAtMost, kNoDifference,
               read + ": GL_DEPTH_TEST on, GL_DEPTH_FUNC GL_LESS (or GL_LEQUAL: the same faces when none ties with a surface)",
               "keep the depth test on (glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS)): the counts depend on which "
               "faces lie in front of the surface and which behind it."});
  c.push_back({p + "ops_not_wrapping", static_cast<double>(s.non_wrapping_ops), Criterion::kAtMost, kNoDifference,
               read + ": GL_INCR or GL_DECR in any of the six stencil operations, in any call",
               "use GL_INCR_WRAP and GL_DECR_WRAP: GL_INCR / GL_DECR stop at 255 and at 0, so a -1 face drawn before "
               "its +1 face leaves 0 + 1 = 1 where the count is 0 (the faces' order within a draw is not fixed)."});
  if (z_fail)
    c.push_back({p + "depth_clamp_off", s.depth_clamp ? 0.0 : 1.0, Criterion::kAtMost, kNoDifference,
                 read + ": GL_DEPTH_CLAMP",
                 "glEnable(GL_DEPTH_CLAMP) for z-fail: a far cap at infinity lands on the far plane, in floating point "
                 "a hair beyond it, and is clipped without clamping; its +1 is lost and the shadow with it."});
  double wrong = 0;
  for (int col = 0; col < kVolumeColumns; ++col) {
    if (!z_fail && !kZPassGraded[col]) continue;
    const int plus = kInsideVolumes[col] % kStencilRange, minus = (kStencilRange - plus) % kStencilRange;
    wrong += s.counts[col] != plus && s.counts[col] != minus;
  }
  c.push_back({p + "counts_wrong", wrong, Criterion::kAtMost, kNoDifference,
               std::string("columns of the host's scene whose stencil count is not the number of volumes around the "
                           "receiver (or its negative) after the pass") + (z_fail ? "" : "; the eye-inside column is not graded"),
               z_fail ? "z-fail counts where the depth test fails (glStencilOpSeparate's second operation, dpfail): "
                        "back faces +1, front faces -1, with wrapping operations and depth clamping; the counts are in "
                        "the metrics (counts)."
                      : "z-pass counts where the depth test passes (glStencilOpSeparate's third operation, dppass): "
                        "front faces +1, back faces -1, wrapping; the counts are in the metrics (counts)."});
  const double restored = 4 - (s.colour_writemask_after[0] + s.colour_writemask_after[1] + s.colour_writemask_after[2] +
                               s.colour_writemask_after[3]) + s.depth_clamp_after + s.cull_face_after;
  c.push_back({p + "state_not_restored", restored, Criterion::kAtMost, kNoDifference,
               "after stencil_pass returned: colour writes off, GL_DEPTH_CLAMP or GL_CULL_FACE left on",
               "end the pass with glColorMask(GL_TRUE, ...) (the lit pass draws colour), glDisable(GL_DEPTH_CLAMP) and "
               "glDisable(GL_CULL_FACE) (the lit pass draws every face)."});
  double picture = 0;
  for (int col = 0; col < kVolumeColumns; ++col) {
    if (!z_fail && !kZPassGraded[col]) continue;
    const float share = kAmbientShare + (kInsideVolumes[col] == 0 ? kLightShare : 0.0f);
    picture += std::abs(s.red[col] - static_cast<int>(std::lround(255.0f * share))) > kRedTolerance;
  }
  c.push_back({p + "picture_wrong", picture, Criterion::kAtMost, kNoDifference,
               "columns whose colour after the lit pass is not ambient (0.25) in shadow and ambient + light (0.75) "
               "where lit, within one 8-bit step (red in the metrics)",
               "the picture is wrong in some columns: the criteria above and the lit pass's say which setting shows."});
  const double errors = (s.gl_error_after_pass != GL_NO_ERROR) + (s.gl_error_after_lit != GL_NO_ERROR);
  c.push_back({p + "gl_errors", errors, Criterion::kAtMost, kNoDifference,
               "glGetError after stencil_pass and after begin_additive_lit_pass",
               "a call failed (see gl_error_after_* in the metrics): check each call's arguments against the OpenGL "
               "3.3 reference."});
}

void add_lit_criteria(const VolumeState& s, CheckResult& result) {
  auto& c = result.criteria;
  const std::string read = "read back with glGet* after begin_additive_lit_pass()";
  c.push_back({"gl_stencil.lit.stencil_test_wrong", lit_test_wrong_counts(s), Criterion::kAtMost, kNoDifference,
               "of the 256 stencil values, those the lit pass's stencil test gets wrong (it must pass 0 only), from "
               "GL_STENCIL_TEST, _FUNC, _REF and _VALUE_MASK (" + read + ")",
               "glEnable(GL_STENCIL_TEST) and glStencilFunc(GL_EQUAL, 0, 0xFF): lit where the count is 0; a count "
               "of 1, 2 or 255 (-1) is inside a volume."});
  const bool additive = s.blend && s.blend_src_rgb == GL_ONE && s.blend_dst_rgb == GL_ONE;
  c.push_back({"gl_stencil.lit.not_additive", additive ? 0.0 : 1.0, Criterion::kAtMost, kNoDifference,
               read + ": GL_BLEND on, GL_BLEND_SRC_RGB and _DST_RGB GL_ONE",
               "glEnable(GL_BLEND) and glBlendFunc(GL_ONE, GL_ONE): the lit pass adds its light to the ambient colour "
               "the first pass left; without blending it replaces it (lit pixels lose their ambient share)."});
  const bool same_surface = s.lit_depth_test && (s.lit_depth_func == GL_EQUAL || s.lit_depth_func == GL_LEQUAL);
  c.push_back({"gl_stencil.lit.depth_func_not_equal", same_surface ? 0.0 : 1.0, Criterion::kAtMost, kNoDifference,
               read + ": GL_DEPTH_TEST on, GL_DEPTH_FUNC GL_EQUAL or GL_LEQUAL (nothing lies nearer than the depth "
               "the ambient pass kept, so both pass exactly its surfaces)",
               "glDepthFunc(GL_EQUAL): the lit pass draws the same surfaces at the depth the ambient pass stored; "
               "GL_LESS passes none of them, GL_ALWAYS lights hidden ones too."});
}

// The GL exercise graded: the file built and run in the sandbox with its own headless OpenGL context,
// z-pass then z-fail, the state and picture it left turned into the gl_stencil.* criteria.
void check_gl_stencil(CheckContext& ctx, CheckResult& result) {
  const auto program = build_gl_exercise(
      ctx, result,
      {kGlExercise, kGlSolution, "09_shadow_volumes",
       {SHADOWLAB_LAB_FOLDER "/gl_volume_setup.h", "renderer/volume_stencil.h", "renderer/gl.h"}, "lab 9's OpenGL part",
       "gl_stencil"});
  if (!program) return;
  const std::vector<VolumeState> states = program->call_many<VolumeState>(std::vector<VolumeCall>{{0}, {1}});
  result.metrics["gl_stencil"] = {{"zpass", pass_json(states[0])}, {"zfail", pass_json(states[1])},
                                  {"lit", lit_json(states[1])}};
  add_pass_criteria(states[0], false, result);
  add_pass_criteria(states[1], true, result);
  add_lit_criteria(states[1], result);
}

void check_volumes(CheckContext& ctx, CheckResult& result) {
  check_gl_stencil(ctx, result);
  const Features hooks = ctx.hooks();
  BandSpec band = grading_band();
  band.fixed_screen_pixels = kBandPixels;
  ParamSet base = ctx.params();
  base.set("view.volumes", 0.0);

  // 1. A directional light and a point light among the objects, from the usual view, both methods: z-pass
  // from outside every volume grades the sides alone (no caps drawn), z-fail the closed volumes.
  for (const char* type : {"directional", "point"}) {
    for (const char* method : {"z-pass", "z-fail"}) {
      ParamSet p = base;
      p.set_from_string("light.type", type);
      p.set_from_string("volume.method", method);
      const bool z_fail = method[2] == 'f';
      const std::string tag = std::string(type) + "_" + (z_fail ? "zfail" : "zpass");
      const auto m = ctx.measure(p, hooks, "lab09_" + tag + "_" + impl_name(ctx.impl), nullptr, band);
      grade(result, tag, m, true, z_fail ? kCapsAdvice : kSidesAdvice);
      if (std::string(type) != "point" || !z_fail) continue;
      // Each silhouette edge once: the point light's side triangles against the solution's.
      const VolumeTriangles graded = ctx.renderer.count_volume_triangles(true);
      const VolumeTriangles reference = solution_triangles(ctx, p, true);
      result.metrics["volume_triangles"] = {{"sides", graded.sides}, {"near_caps", graded.near_caps},
                                            {"far_caps", graded.far_caps}, {"solution_sides", reference.sides}};
      long open_edges = 0;
      for (const auto& mesh : ctx.renderer.volume_report()) open_edges += static_cast<long>(mesh.open_edges);
      result.criteria.push_back({"silhouettes.side_triangles_ratio_to_solution", ratio(graded.sides, reference.sides),
                                 Criterion::kAtMost, kMaxSidesRatio + ratio(2 * open_edges, reference.sides),
                                 "each silhouette edge extruded once: no more side triangles than the solution's (plus one quad per open edge)",
                                 "extrude only the silhouette edges, each once (from its light-facing triangle): extruding "
                                 "every edge gives the same shadows with several times the triangles and fill."});
    }
  }
  // Held-out directional lights, drawn from the seed, within 60 degrees of the lab's azimuth (from
  // farther round, the shadows fall behind the objects as the camera sees them): one sun in each band of
  // kHeldOutSuns, so that every seed also grades a low sun, whose long shadows reach far from their casters.
  {
    std::mt19937 rng = ctx.held_out_rng();
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const auto& sun : kHeldOutSuns) {
      ParamSet p = base;
      p.set_from_string("light.type", "directional");
      p.set_from_string("volume.method", "z-fail");
      const float azimuth = std::fmod(base.get(param::light_azimuth) + 120.0f * (unit(rng) - 0.5f) + 360.0f, 360.0f);
      const float elevation = sun.min_elevation + (sun.max_elevation - sun.min_elevation) * unit(rng);
      p.set("light.azimuth", azimuth);
      p.set("light.elevation", elevation);
      const std::string tag = std::string("held_out_") + sun.name + "zfail";
      grade(result, tag, ctx.measure(p, hooks, "lab09_held_out_" + std::string(sun.name) + impl_name(ctx.impl), nullptr, band),
            true);
      result.conditions.push_back({{"tag", tag}, {"light_azimuth", azimuth}, {"light_elevation", elevation}});
    }
  }
  report_adjacency(ctx, result);

  // 2. The camera inside the big box's shadow volume: z-fail stays right, z-pass counts every volume
  // the eye is in once too few.
  ParamSet p = base;
  p.set_from_string("light.type", "directional");
  const glm::vec3 to_light = direction_from_angles(p.get(param::light_azimuth), p.get(param::light_elevation));
  const bool eye_in_shadow = ctx.oracle().occluded(kInsideEye, to_light, std::numeric_limits<float>::infinity());
  result.metrics["inside"] = {{"eye", {kInsideEye.x, kInsideEye.y, kInsideEye.z}}, {"eye_in_shadow", eye_in_shadow}};
  result.criteria.push_back({"inside.eye_in_shadow", eye_in_shadow ? 1.0 : 0.0, Criterion::kAtLeast, 1,
                             "the oracle confirms the eye is inside a shadow volume"});
  const OrbitCamera camera = camera_looking_at(kInsideEye, kInsideTarget, 0.05f, 100.0f);
  for (const char* method : {"z-fail", "z-pass"}) {
    p.set_from_string("volume.method", method);
    const std::string tag = std::string("inside_") + (method[2] == 'f' ? "zfail" : "zpass");
    const auto m = ctx.measure(p, hooks, "lab09_" + tag + "_" + impl_name(ctx.impl), nullptr, band, 960, 540, &camera);
    grade(result, tag, m, method[2] == 'f');
    if (method[2] == 'p')
      result.criteria.push_back({"inside_zpass.error", 1.0 - interior_agreement(m.metrics), Criterion::kAtLeast,
                                 kMinZPassInsideError, "z-pass visibly fails with the eye inside a volume"});
  }
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Stencil shadow volumes";
  lab.summary = "Find silhouette edges from adjacency in a geometry shader, extrude them to infinity, cap the volumes for z-fail.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.gl_exercise_files = {SHADOWLAB_LAB_FOLDER "/gl_volume_stencil.cpp"};
  lab.gl_solution_files = {"renderer/volume_stencil.cpp"};
  lab.params = specs_of(param::light_type, param::light_position_x, param::light_position_y, param::light_position_z,
                        param::light_cone_deg, param::volume_method);
  ParamSpec wire = param::view_volumes.spec(), quad = param::view_debug_quad.spec();
  wire.default_value = 0.0;
  quad.default_value = 0.0;  // there is no shadow map to show
  lab.params.push_back(wire);
  lab.params.push_back(quad);
  lab.params.push_back(param::view_flat_normals.spec());  // the facets the volumes are extruded from
  // In the window a preset sets only its own keys over the current values (apply_preset), and Page Down
  // steps through these in order: "z-pass" sets the directional light its camera was placed for (the big
  // box's volume), and each debug view turns the other off.
  lab.presets = {
      {"point light", "A point light among the objects.", {{"light.type", "point"}}},
      {"z-pass", "Count the faces in front, the camera standing in the big box's shadow: every count is off by one, "
       "so shadow and light swap.", {{"volume.method", "z-pass"}, {"light.type", "directional"}},
       {.provokes = "z-pass failure", .fixed_by = "z-fail"}, {.camera = "eye=-4.2,0.5,0 target=0.5,0.3,-0.5 fov=60"}},
      {"z-fail", "Count the faces behind (the default): right wherever the camera stands.", {{"volume.method", "z-fail"}}},
      {"wireframe", "The extruded volumes as lines (geometry shader).", {{"view.volumes", "true"}, {"view.flat_normals", "false"}}},
      {"flat normals", "Each triangle in the colour of its face normal, computed by a geometry shader; the vertex "
       "normals as lines over it.", {{"view.flat_normals", "true"}, {"view.normals", "true"}, {"view.volumes", "false"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.technique = ShadowTechnique::ShadowVolumes;
    hooks.includes["lab/volume.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_volumes;
  // Exact hard shadows on closed meshes, the GPU reference (no map to size).
  lab.bench = {{"volumes", "shadow volumes", {{"volume.method", "z-fail"}}, false}};
  return lab;
}

}  // namespace shadowlab
