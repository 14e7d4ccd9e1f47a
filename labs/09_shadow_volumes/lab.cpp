// Lab 9: stencil shadow volumes (lecture 9).
// Demonstrates: silhouette edges found per triangle in a geometry shader from GL_TRIANGLES_ADJACENCY,
// side quads extruded to infinity (w = 0) under a projection with its far plane at infinity, z-pass
// and z-fail (Carmack's reverse) counting in a two-sided stencil pass, the ambient / stencil / additive
// lit passes, and the adjacency report of open and non-manifold edges. Check: agreement with the oracle
// on non-edge pixels for a directional and a point light, and with the camera inside a shadow volume,
// where z-fail must stay right and z-pass is shown failing.
#include <cmath>
#include <cstdio>
#include <random>
#include <limits>

#include "labs/check.h"
#include "labs/lab.h"
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
// wrong (measured 40 %, README).
constexpr double kMinZPassInsideError = 0.05;

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

void grade(CheckResult& result, const std::string& tag, const CheckContext::Measurement& m, bool graded) {
  const double agreement = interior_agreement(m.metrics);
  result.metrics[tag] = to_json(m.metrics);
  result.metrics[tag]["interior_agreement"] = agreement;
  std::printf("    %-22s agreement %.5f  (acne %.5f, leak %.5f, %llu interior px)\n", tag.c_str(), agreement,
              m.metrics.acne_rate, m.metrics.leak_rate,
              static_cast<unsigned long long>(m.metrics.interior_lit + m.metrics.interior_shadowed));
  if (graded) {
    result.criteria.push_back({tag + ".interior_agreement", agreement, Criterion::kAtLeast, kMinAgreement,
                               "exact hard shadows: >= 99.5 % of non-edge pixels",
                               "every silhouette edge of a lit triangle extruded once; with u_caps (z-fail) close each volume "
                               "with the lit triangles at the near end and the same triangles at infinity at the far end."});
    require_measurable(result, tag, m.metrics);
  }
}

void check_volumes(CheckContext& ctx, CheckResult& result) {
  const Features hooks = ctx.hooks();
  BandSpec band = grading_band();
  band.fixed_screen_pixels = kBandPixels;
  ParamSet base = ctx.params();
  base.set("view.volumes", 0.0);

  // 1. A directional light and a point light among the objects, from the usual view, both methods.
  for (const char* type : {"directional", "point"}) {
    for (const char* method : {"z-fail", "z-pass"}) {
      ParamSet p = base;
      p.set_from_string("light.type", type);
      p.set_from_string("volume.method", method);
      const std::string tag = std::string(type) + "_" + (method[2] == 'f' ? "zfail" : "zpass");
      const auto m = ctx.measure(p, hooks, "lab09_" + tag + "_" + impl_name(ctx.impl), nullptr, band);
      grade(result, tag, m, method[2] == 'f');
    }
  }
  // A held-out directional light, drawn from the seed, within 60 degrees of the lab's azimuth (from
  // farther round, the shadows fall behind the objects as the camera sees them).
  {
    std::mt19937 rng = ctx.held_out_rng();
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    ParamSet p = base;
    p.set_from_string("light.type", "directional");
    p.set_from_string("volume.method", "z-fail");
    const float azimuth = std::fmod(base.get_float("light.azimuth") + 120.0f * (unit(rng) - 0.5f) + 360.0f, 360.0f);
    const float elevation = 25.0f + 55.0f * unit(rng);
    p.set("light.azimuth", azimuth);
    p.set("light.elevation", elevation);
    grade(result, "held_out_zfail", ctx.measure(p, hooks, "lab09_held_out_" + std::string(impl_name(ctx.impl)), nullptr, band),
          true);
    result.conditions.push_back({{"tag", "held_out_zfail"}, {"light_azimuth", azimuth}, {"light_elevation", elevation}});
  }
  report_adjacency(ctx, result);

  // 2. The camera inside the big box's shadow volume: z-fail stays right, z-pass counts every volume
  // the eye is in once too few.
  ParamSet p = base;
  p.set_from_string("light.type", "directional");
  const glm::vec3 to_light = direction_from_angles(p.get_float("light.azimuth"), p.get_float("light.elevation"));
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
  lab.summary = "Silhouettes from adjacency in a geometry shader, extruded to infinity; z-pass vs z-fail.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = technique_param_specs(
      {"light.type", "light.position_x", "light.position_y", "light.position_z", "light.cone_deg", "volume.method"});
  ParamSet base(renderer_param_specs());
  ParamSpec wire = *base.find("view.volumes"), quad = *base.find("view.debug_quad");
  wire.default_value = 0.0;
  quad.default_value = 0.0;  // there is no shadow map to show
  lab.params.push_back(wire);
  lab.params.push_back(quad);
  lab.presets = {
      {"point light", "A point light among the objects.", {{"light.type", "point"}}},
      {"z-pass", "Count the faces in front: right until the camera enters a volume.", {{"volume.method", "z-pass"}}},
      {"wireframe", "The extruded volumes as lines (geometry shader).", {{"view.volumes", "true"}}},
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
