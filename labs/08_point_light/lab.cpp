// Lab 8: a point light with an omnidirectional (cube) shadow map.
// Demonstrates: six 90-degree perspective views in GL's cube-map face order and orientation, drawn in
// six passes or in one with a geometry shader choosing the layer (gl_Layer), each storing the distance
// to the light (R32F); face selection in the lit pass (the GL specification's cube-map rule, written
// out on a six-layer array); a comparison of distances with a bias in world units growing with distance
// and slope. The student writes what the faces store (exercise_store.glsl) and the shadow test with its
// face selection (exercise.glsl). Check, part by part: the stored value on chosen points (probe), the face
// and texel selected for chosen directions (probe), the bias of the comparison (probe), then images: the
// light among the default scene's objects (shadows on every side of it), in both drawing modes and at
// held-out places and map sizes, against the oracle casting toward the light's position.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "grading/check.h"
#include "grading/lab.h"
#include "grading/probe.h"

namespace shadowlab {

namespace {

constexpr const char* kExerciseStore = SHADOWLAB_LAB_FOLDER "/exercise_store.glsl";
constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolutionStore = "shaders/cube/store.glsl";  // the renderer's own shadow pass
constexpr const char* kSolution = "shaders/shadow/cube.glsl";       // the renderer's own cube test
constexpr std::size_t kStoreSlot = 0, kTestSlot = 1;

// "Shadows on every side": in each quarter around the light (in the ground plane) at least this many
// truly shadowed interior pixels (the measured minimum is in INSTRUCTOR.md; the limit is about a quarter of it); a light placed beside the scene
// instead of among its objects leaves one or two quarters with none.
constexpr double kMinShadowedPerQuarter = 2000;
// The camera looks down steeply so the shadows behind the objects are not hidden by them.
constexpr float kCameraPitch = 60.0f;

// The bias alone (grading/probe.h): a point light at the origin, a cube map whose every texel holds an
// occluder at one of three distances, at two map sizes' texel angles (2 / size), along a direction
// that lands on the -Y face off its centre, at angles of incidence from head-on down to grazing (n . l
// 0.05 is 87 degrees, past the course's cap on tan at 84): a slope term wrong only at grazing light (tan
// capped at 45 degrees, say) passes n . l = 1 and 0.5 alone.
constexpr double kProbeDistances[] = {1.0, 3.0, 8.0};
constexpr int kProbeMapSizes[] = {512, 1024};
constexpr double kProbeSlope = 2.0;
constexpr double kProbeNdotL[] = {1.0, 0.5, 0.2, 0.05};

// Six layers of size x size texels, layer-major (layer 0 first), bottom row first; nearest, clamped.
GlTexture probe_faces(const std::vector<float>& texels, int size) {
  GlTexture t = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D_ARRAY, t.id());
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_R32F, size, size, 6, 0, GL_RED, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return t;
}

void bind_probe_faces(GLuint program, const GlTexture& faces) {
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D_ARRAY, faces.id());
  glActiveTexture(GL_TEXTURE0);
  set_uniform(program, "u_shadow_faces", 2);
}

void unbind_probe_faces() {
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glActiveTexture(GL_TEXTURE0);
}

void probe_bias(CheckContext& ctx, CheckResult& result) {
  std::vector<float> angles;
  for (int size : kProbeMapSizes) angles.push_back(2.0f / static_cast<float>(size));
  std::vector<BiasThreshold> thresholds;
  for (double distance : kProbeDistances) {
    const GlTexture faces = probe_faces(std::vector<float>(6 * 16, static_cast<float>(distance)), 4);
    BiasSweep sweep;
    sweep.distance = distance;
    sweep.direction = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
    sweep.texel_angles = angles;
    sweep.n_dot_l.assign(std::begin(kProbeNdotL), std::end(kProbeNdotL));
    sweep.setup = [&](GLuint program, double, float angle) {
      bind_probe_faces(program, faces);
      set_uniform(program, "u_light_position", glm::vec3(0.0f));
      set_uniform(program, "u_texel_angle", angle);
      set_uniform(program, "u_bias_slope", static_cast<float>(kProbeSlope));
    };
    const auto t = sweep_bias(ctx.hooks_with_only(kTestSlot), sweep);
    thresholds.insert(thresholds.end(), t.begin(), t.end());
  }
  unbind_probe_faces();
  grade_bias_thresholds(result, thresholds, kProbeSlope);
}

// Face selection alone: six layers of kFaceTexels^2 texels, each holding its own number, and directions
// (of random lengths) away from ties between components and from texel borders; each must read the
// texel the GL specification's cube-map rule picks.
constexpr int kFaceTexels = 16;
constexpr int kFaceProbeDirections = 3000;
constexpr double kTieMargin = 0.02;      // the largest component this much above the next (relative)
constexpr double kTexelMargin = 0.05;    // of a texel, from its borders
constexpr double kMaxFaceMismatch = 0.002;

// GL's table: face, and the place on it (sc / |ma|, tc / |ma|) in [-1, 1].
struct FaceHit {
  int face;
  double s, t;
};
FaceHit gl_cube_face(const glm::dvec3& d) {
  const glm::dvec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x > 0 ? FaceHit{0, -d.z / a.x, -d.y / a.x} : FaceHit{1, d.z / a.x, -d.y / a.x};
  if (a.y >= a.z) return d.y > 0 ? FaceHit{2, d.x / a.y, d.z / a.y} : FaceHit{3, d.x / a.y, -d.z / a.y};
  return d.z > 0 ? FaceHit{4, d.x / a.z, -d.y / a.z} : FaceHit{5, -d.x / a.z, -d.y / a.z};
}

void probe_face_selection(CheckContext& ctx, CheckResult& result) {
  std::vector<float> texels(6 * kFaceTexels * kFaceTexels);
  for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<float>(i + 1);  // exact in float32
  std::mt19937 rng = ctx.held_out_rng();
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> length(0.5, 20.0);
  ProbeRequest request;
  request.fragment = "shaders/probe/cube_lookup.frag";
  std::vector<float> expected;
  std::vector<int> per_face(6, 0);
  while (static_cast<int>(expected.size()) < kFaceProbeDirections) {
    glm::dvec3 d(gauss(rng), gauss(rng), gauss(rng));
    if (glm::length(d) < 1e-3) continue;
    d = glm::normalize(d);
    glm::dvec3 a = glm::abs(d);
    double c[3] = {a.x, a.y, a.z};
    std::sort(c, c + 3);
    if (c[2] - c[1] < kTieMargin * c[2]) continue;
    const FaceHit hit = gl_cube_face(d);
    const double u = 0.5 * (hit.s + 1.0) * kFaceTexels, v = 0.5 * (hit.t + 1.0) * kFaceTexels;
    auto near_border = [](double x) { const double f = x - std::floor(x); return f < kTexelMargin || f > 1.0 - kTexelMargin; };
    if (near_border(u) || near_border(v)) continue;
    const int x = std::clamp(static_cast<int>(u), 0, kFaceTexels - 1), y = std::clamp(static_cast<int>(v), 0, kFaceTexels - 1);
    expected.push_back(texels[static_cast<std::size_t>((hit.face * kFaceTexels + y) * kFaceTexels + x)]);
    ++per_face[static_cast<std::size_t>(hit.face)];
    request.in0.push_back(glm::vec4(glm::vec3(d * length(rng)), 0.0f));
  }
  const GlTexture faces = probe_faces(texels, kFaceTexels);
  request.passes.push_back([&](GLuint program) { bind_probe_faces(program, faces); });
  const std::vector<float> v = run_probe(ctx.hooks_with_only(kTestSlot), request).at(0);
  unbind_probe_faces();
  double wrong = 0, wrong_face = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (v[i] == expected[i]) continue;
    ++wrong;
    // The texel's layer: values 1.. count texels layer by layer.
    const auto layer = [](float value) { return static_cast<int>(std::floor((value - 1.0f) / (kFaceTexels * kFaceTexels))); };
    if (!std::isfinite(v[i]) || layer(v[i]) != layer(expected[i])) ++wrong_face;
  }
  const double n = static_cast<double>(v.size());
  result.metrics["face_probe"] = {{"texels_per_side", kFaceTexels}, {"directions", v.size()}, {"per_face", per_face},
                                  {"wrong_texel", wrong}, {"wrong_face", wrong_face}};
  const std::string why = "probe: 3,000 directions, six layers of numbered texels, GL's cube-map selection rule";
  result.criteria.push_back({"faces.wrong_face", wrong_face / n, Criterion::kAtMost, kMaxFaceMismatch, why,
                             "the face is the one of the direction's largest component (in magnitude), + or - by its "
                             "sign, in the order +X, -X, +Y, -Y, +Z, -Z (layers 0-5)."});
  result.criteria.push_back({"faces.wrong_texel", wrong / n, Criterion::kAtMost, kMaxFaceMismatch, why,
                             "on the face, divide the other two components by the largest one's magnitude and map "
                             "[-1, 1] to [0, 1], with the signs of GL's cube-map table (the faces are stored as GL "
                             "renders a cube map's faces)."});
}

// What the faces store, alone: value_to_store at points around a light, against the distance.
constexpr int kStoreProbePoints = 2000;
constexpr double kMaxStoreRelativeError = 1e-5;  // float32: length() is within a few ulps
constexpr double kMaxStoreMismatch = 0;          // the share of points outside it: none

void probe_store(CheckContext& ctx, CheckResult& result) {
  std::mt19937 rng = ctx.held_out_rng();
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> length(0.1, 30.0);
  const glm::vec3 light(1.5f, 2.25f, -0.75f);
  ProbeRequest request;
  request.fragment = "shaders/probe/cube_store.frag";
  std::vector<double> expected;
  while (static_cast<int>(expected.size()) < kStoreProbePoints) {
    glm::dvec3 d(gauss(rng), gauss(rng), gauss(rng));
    if (glm::length(d) < 1e-3) continue;
    const glm::vec3 p = light + glm::vec3(glm::normalize(d) * length(rng));
    expected.push_back(glm::length(glm::dvec3(p) - glm::dvec3(light)));
    request.in0.push_back(glm::vec4(p, 0.0f));
  }
  request.passes.push_back([&](GLuint program) { set_uniform(program, "u_light_position", light); });
  const std::vector<float> v = run_probe(ctx.hooks_with_only(kStoreSlot), request).at(0);
  double wrong = 0, worst = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double error = std::abs(v[i] - expected[i]) / expected[i];
    wrong += !(error <= kMaxStoreRelativeError);
    worst = std::max(worst, std::isfinite(error) ? error : 1e30);
  }
  result.metrics["store_probe"] = {{"points", v.size()}, {"wrong", wrong}, {"worst_relative_error", worst}};
  result.criteria.push_back({"store.distance_mismatch", wrong / static_cast<double>(v.size()), Criterion::kAtMost, kMaxStoreMismatch,
                             "probe: 2,000 points around a light, the Euclidean distance within 1e-5 (relative)",
                             "store the distance from the light to the surface, in world units: the lit pass compares one "
                             "number per direction, whatever face it falls on (a depth is measured along each face's own "
                             "axis and is not linear in distance)."});
}

const HardLimits kLimits{
    .lit_advice = "acne: compare the fragment's distance to the light with the stored distance, biased by a texel's "
                  "footprint at that distance (distance x u_texel_angle), growing with the slope.",
    .shadow_advice = "light where there should be shadow: select the face along the direction from the light to the "
                     "fragment (the faces were rendered looking outward from the light), and compare distances, not depths."};

void check_point(CheckContext& ctx, CheckResult& result) {
  // 1. Each part alone: what the shadow pass stores, the face selection, the comparison's bias.
  probe_store(ctx, result);
  probe_face_selection(ctx, result);
  probe_bias(ctx, result);
  // 2. Images with everything together.
  ParamSet params = ctx.params();
  params.set("view.debug_quad", 0.0);
  const Features hooks = ctx.hooks();
  const OrbitCamera camera = OrbitCamera::framing(ctx.scene().bounds(), 30.0f, kCameraPitch);
  Renderer& r = ctx.renderer;
  std::vector<float> faces[2][6];
  for (int single = 0; single < 2; ++single) {
    ParamSet p = params;
    p.set("point.single_pass", single);
    const std::string tag = single ? "one_pass" : "six_passes";
    const auto m = ctx.measure(p, hooks, "lab08_" + tag + "_" + impl_name(ctx.impl), nullptr, grading_band(), 960, 540, &camera);
    grade_hard_shadow(result, tag, m.metrics, kLimits);
    result.metrics[tag]["interior_agreement"] = interior_agreement(m.metrics);
    int size = 0;
    for (int f = 0; f < 6; ++f) faces[single][f] = r.read_cube_face(f, &size);
    if (single) continue;
    // Shadows on every side: truly shadowed interior pixels per quarter around the light.
    const GBuffer g = r.read_gbuffer();
    double quarter[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < g.position.size(); ++i) {
      if (!m.truth.valid[i] || m.truth.lit[i] || !m.truth.interior[i]) continue;
      const glm::vec3 d = g.position[i] - r.light_position();
      quarter[(d.x >= 0 ? 1 : 0) + (d.z >= 0 ? 2 : 0)] += 1;
    }
    result.metrics["shadowed_pixels_per_quarter"] = {quarter[0], quarter[1], quarter[2], quarter[3]};
    result.criteria.push_back({"scene.min_shadowed_pixels_per_quarter", *std::min_element(quarter, quarter + 4),
                               Criterion::kAtLeast, kMinShadowedPerQuarter, "the light stands among the objects"});
  }
  // Both modes rasterise the same triangles through the same matrices: the same distances, bit for bit.
  double max_difference = 0.0;
  for (int f = 0; f < 6; ++f)
    for (std::size_t i = 0; i < faces[0][f].size(); ++i)
      max_difference = std::max(max_difference, static_cast<double>(std::abs(faces[0][f][i] - faces[1][f][i])));
  // Reported, not graded: both modes run the same store function; the renderer does the layering.
  result.metrics["cube_max_difference_six_vs_one_pass"] = max_difference;
  // Held-out places among the objects, with other map sizes, drawn from the seed.
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const char* sizes[] = {"256", "512", "2048"};
  for (const char* tag : {"held_out_1", "held_out_2"}) {
    ParamSet p = params;
    const glm::vec3 at(params.get(param::light_position_x) + 1.2f * (unit(rng) - 0.5f), 2.0f + 2.0f * unit(rng),
                       params.get(param::light_position_z) + 1.2f * (unit(rng) - 0.5f));
    const std::string size = sizes[std::uniform_int_distribution<int>(0, 2)(rng)];
    p.set("light.position_x", at.x);
    p.set("light.position_y", at.y);
    p.set("light.position_z", at.z);
    p.set_from_string("shadow.map_size", size);
    const auto m = ctx.measure(p, hooks, std::string("lab08_") + tag + "_" + impl_name(ctx.impl), nullptr, grading_band(),
                               960, 540, &camera);
    grade_hard_shadow(result, tag, m.metrics, kLimits);
    result.conditions.push_back({{"tag", tag}, {"light_position", {at.x, at.y, at.z}}, {"map_size", size}});
  }
}

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Point light: cube shadow map";
  lab.summary = "Six 90-degree faces storing the distance to the light: what to store, which face and texel to read, how to compare.";
  lab.exercise_files = {kExerciseStore, kExercise};
  lab.solution_files = {kSolutionStore, kSolution};
  ParamSpec slope = param::shadow_slope_bias.spec();
  slope.default_value = 2.0;
  lab.params = {slope};
  for (const auto& spec :
       specs_of(param::light_position_x, param::light_position_y, param::light_position_z, param::point_single_pass))
    lab.params.push_back(spec);
  lab.presets = {
      {"among the objects", "The check's place: shadows on every side.", {{"light.position_x", "-0.6"}, {"light.position_y", "3"}, {"light.position_z", "0.2"}}},
      {"low", "Just above the ground: long shadows in every direction.", {{"light.position_y", "1.5"}}},
      {"one pass", "All six faces in one draw, the geometry shader choosing the layer.", {{"point.single_pass", "true"}}},
  };
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.light = LightType::Point;
    hooks.includes["lab/cube_store.glsl"] = files.at(kStoreSlot).string();
    hooks.includes["lab/visibility.glsl"] = files.at(kTestSlot).string();
    return hooks;
  };
  lab.check = check_point;
  return lab;
}

}  // namespace shadowlab
