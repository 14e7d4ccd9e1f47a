// Lab 8: a point light with an omnidirectional (cube-map) shadow.
// Demonstrates: six 90-degree perspective views in GL's cube-map face order and orientation, each
// storing the distance to the light (R32F), drawn in six passes or in one with a geometry shader
// choosing the face (gl_Layer); the lookup by the direction from the light to the fragment; a bias in
// world units growing with distance. Check: the light stands among the default scene's objects, so
// shadows fall on every side of it; graded against the oracle casting toward the light's position, in
// both drawing modes, which must store the same distances.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "labs/check.h"
#include "labs/lab.h"
#include "labs/probe.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/shadow/cube.glsl";  // the renderer's own cube test

// "Shadows on every side": in each quarter around the light (in the ground plane) at least this many
// truly shadowed interior pixels. Measured minimum 8,440 (README), the limit about a quarter of it; a light placed beside the scene
// instead of among its objects leaves one or two quarters with none.
constexpr double kMinShadowedPerQuarter = 2000;
// The camera looks down steeply so the shadows behind the objects are not hidden by them.
constexpr float kCameraPitch = 60.0f;

// The bias alone (labs/probe.h): a point light at the origin, a cube map whose every texel holds an
// occluder at one of three distances, at two map sizes' texel angles (2 / size), along a direction
// that lands on the -Y face off its centre.
constexpr double kProbeDistances[] = {1.0, 3.0, 8.0};
constexpr int kProbeMapSizes[] = {512, 1024};
constexpr double kProbeSlope = 2.0;

GlTexture uniform_cube(float value) {
  GlTexture t = GlTexture::create();
  glBindTexture(GL_TEXTURE_CUBE_MAP, t.id());
  const std::vector<float> texels(16, value);
  for (int face = 0; face < 6; ++face)
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_R32F, 4, 4, 0, GL_RED, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  return t;
}

void probe_bias(CheckContext& ctx, CheckResult& result) {
  std::vector<float> angles;
  for (int size : kProbeMapSizes) angles.push_back(2.0f / static_cast<float>(size));
  std::vector<BiasThreshold> thresholds;
  for (double distance : kProbeDistances) {
    const GlTexture cube = uniform_cube(static_cast<float>(distance));
    BiasSweep sweep;
    sweep.distance = distance;
    sweep.direction = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
    sweep.texel_angles = angles;
    sweep.setup = [&](GLuint program, double, float angle) {
      glActiveTexture(GL_TEXTURE2);
      glBindTexture(GL_TEXTURE_CUBE_MAP, cube.id());
      glActiveTexture(GL_TEXTURE0);
      set_uniform(program, "u_shadow_cube", 2);
      set_uniform(program, "u_light_position", glm::vec3(0.0f));
      set_uniform(program, "u_texel_angle", angle);
      set_uniform(program, "u_bias_slope", static_cast<float>(kProbeSlope));
    };
    const auto t = sweep_bias(ctx.hooks(), sweep);
    thresholds.insert(thresholds.end(), t.begin(), t.end());
  }
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glActiveTexture(GL_TEXTURE0);
  grade_bias_thresholds(result, thresholds, kProbeSlope);
}

const HardLimits kLimits{
    .lit_advice = "acne: compare the fragment's distance to the light with the stored distance, biased by a texel's "
                  "footprint at that distance (distance x u_texel_angle), growing with the slope.",
    .shadow_advice = "shadows missing: look the cube up along the direction from the light to the fragment (the shadow "
                     "pass looked outward from the light), and compare distances, not depths."};

void check_point(CheckContext& ctx, CheckResult& result) {
  probe_bias(ctx, result);
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
  // Reported, not graded: the renderer draws the cube maps, the student's file only reads them.
  result.metrics["cube_max_difference_six_vs_one_pass"] = max_difference;
  // Held-out places among the objects, with other map sizes, drawn from the seed.
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const char* sizes[] = {"256", "512", "2048"};
  for (const char* tag : {"held_out_1", "held_out_2"}) {
    ParamSet p = params;
    const glm::vec3 at(params.get_float("light.position_x") + 1.2f * (unit(rng) - 0.5f), 2.0f + 2.0f * unit(rng),
                       params.get_float("light.position_z") + 1.2f * (unit(rng) - 0.5f));
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
  lab.summary = "Six 90-degree faces storing the distance to the light; look up by direction, compare distances.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  ParamSet base(renderer_param_specs());
  ParamSpec slope = *base.find("shadow.slope_bias");
  slope.default_value = 2.0;
  lab.params = {slope};
  for (const auto& spec :
       technique_param_specs({"light.position_x", "light.position_y", "light.position_z", "point.single_pass"}))
    lab.params.push_back(spec);
  lab.presets = {
      {"among the objects", "The check's place: shadows on every side.", {{"light.position_x", "-0.6"}, {"light.position_y", "3"}, {"light.position_z", "0.2"}}},
      {"low", "Just above the ground: long shadows in every direction.", {{"light.position_y", "1.5"}}},
      {"one pass", "All six faces in one draw, the geometry shader choosing the layer.", {{"point.single_pass", "true"}}},
  };
  lab.make_hooks = visibility_lab_hooks(LightType::Point);
  lab.check = check_point;
  return lab;
}

}  // namespace shadowlab
