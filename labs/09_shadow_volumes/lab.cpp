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
#include <random>
#include <limits>

#include "grading/check.h"
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

void check_volumes(CheckContext& ctx, CheckResult& result) {
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
  lab.params = specs_of(param::light_type, param::light_position_x, param::light_position_y, param::light_position_z,
                        param::light_cone_deg, param::volume_method);
  ParamSpec wire = param::view_volumes.spec(), quad = param::view_debug_quad.spec();
  wire.default_value = 0.0;
  quad.default_value = 0.0;  // there is no shadow map to show
  lab.params.push_back(wire);
  lab.params.push_back(quad);
  lab.params.push_back(param::view_flat_normals.spec());  // the facets the volumes are extruded from
  lab.presets = {
      {"point light", "A point light among the objects.", {{"light.type", "point"}}},
      {"z-pass", "Count the faces in front, the camera standing in the big box's shadow: every count is off by one, "
       "so shadow and light swap.", {{"volume.method", "z-pass"}},
       {.provokes = "z-pass failure", .fixed_by = "z-fail"}, {.camera = "eye=-4.2,0.5,0 target=0.5,0.3,-0.5 fov=60"}},
      {"z-fail", "Count the faces behind (the default): right wherever the camera stands.", {{"volume.method", "z-fail"}}},
      {"wireframe", "The extruded volumes as lines (geometry shader).", {{"view.volumes", "true"}}},
      {"flat normals", "Each triangle in the colour of its face normal, computed by a geometry shader; the vertex "
       "normals as lines over it.", {{"view.flat_normals", "true"}, {"view.normals", "true"}}},
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
