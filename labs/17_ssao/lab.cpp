// Lab 17: screen-space ambient occlusion (SSAO), the shadows of indirect light.
// Demonstrates: a point's ambient light is the share of the hemisphere around its normal that nothing
// nearby hides; SSAO estimates it from the depth buffer alone, with a kernel of samples in the hemisphere
// (oriented by the normal, rotated per pixel by a 4 x 4 noise texture, blurred over the noise's tile).
// The renderer's SSAO pass (renderer/ssao_pass.h) calls the student's ssao_open (lab/ssao.glsl).
// Check: the AO buffer (blurred, as shown) against the AO truth (oracle/ao_truth.h: the cosine-weighted
// unoccluded share of the hemisphere within the same radius, by ray casting) on interior pixels (no depth
// discontinuity within kInteriorMargin pixels), and the width of the false dark halos beside depth
// discontinuities; at the lab's camera and radius, and at two held-out cameras, radii and scenes drawn
// from the seed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "core/ao_params.h"
#include "core/image_io.h"
#include "grading/check.h"
#include "grading/lab.h"
#include "oracle/ao_truth.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/ssao/ssao_core.glsl";

// The frames graded, and the AO truth's rays per pixel (oracle/ao_truth.h's default grid).
constexpr int kWidth = 640, kHeight = 360;
constexpr float kRadius = 0.5f;  // the lab's AO radius (ssao.radius's default here)
constexpr float kHeldOutMinRadius = 0.3f, kHeldOutMaxRadius = 1.0f;
// A pixel is on a depth discontinuity when a 4-neighbour lies off its tangent plane by more than this share
// of the radius (a convex or concave crease bends the plane by about a pixel's footprint, far less).
constexpr float kDiscontinuityShare = 0.1f;
// Interior pixels: no discontinuity (nor the background) within this many pixels (the blur's reach is 2).
constexpr int kInteriorMargin = 4;
// The halo: within kHaloReach pixels of the far side of a discontinuity, pixels the truth sees open
// (>= kHaloOpenTruth) that the AO draws darker by more than kHaloDrop; their count over the far-side
// discontinuity pixels' is the halo's mean width in pixels.
constexpr int kHaloReach = 24;
constexpr double kHaloOpenTruth = 0.9;
constexpr double kHaloDrop = 0.25;
// The interior's two regions graded apart (the open floor would otherwise drown the creases): pixels the
// truth sees open (at least kOpenTruth) and pixels it sees occluded (below kOccludedTruth).
constexpr double kOpenTruth = 0.95;
constexpr double kOccludedTruth = 0.8;
constexpr float kFlatMesh = 1e-3f;  // a mesh thinner than this in y is a floor, not an object to frame
// Limits. Open interior: the AO truth's own error. The darkening share and the halo: measured with the
// solution over the three cases of seed 1 (INSTRUCTOR.md quotes the run): share 0.219-0.229, halo 0-0.298 px.
constexpr double kOpenErrorLimit = kAoTruthError;
constexpr double kMinDarkeningShare = 0.15;
constexpr double kMaxDarkeningShare = 0.35;
constexpr double kHaloWidthLimit = 0.6;

struct AoCase {
  std::string tag;
  std::string scene;  // "default" or "stacked"
  float yaw = 30.0f, pitch = 30.0f;
  float radius = kRadius;
};

struct AoFigures {
  double mean_error = 0.0;  // over interior pixels
  double mean_signed = 0.0; // AO minus truth
  double open_error = 0.0;      // over interior pixels the truth sees open (>= kOpenTruth)
  double occluded_error = 0.0;  // over interior pixels the truth sees occluded (< kOccludedTruth)
  long open = 0, occluded = 0;
  double captured = 0.0;  // over the occluded interior: the AO's darkening (1 - AO) summed, over the truth's
  double halo_width = 0.0;  // pixels
  long interior = 0, edges = 0, halo_pixels = 0;
  double truth_seconds = 0.0;
  std::uint64_t rays = 0;
};

// Depth discontinuities: 1 where this pixel is the far side (a neighbour lies in front of its plane), 2
// where it is the near side; 0 elsewhere. Uncovered neighbours count as far background (near side).
std::vector<std::uint8_t> discontinuities(const GBuffer& g, float radius) {
  const int w = g.width, h = g.height;
  std::vector<std::uint8_t> d(g.position.size(), 0);
  const float tau = kDiscontinuityShare * radius;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!g.covered[i]) continue;
      const int nx[4] = {x - 1, x + 1, x, x};
      const int ny[4] = {y, y, y - 1, y + 1};
      for (int k = 0; k < 4; ++k) {
        if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
        const std::size_t j = static_cast<std::size_t>(ny[k]) * w + nx[k];
        if (!g.covered[j]) {
          d[i] = std::max<std::uint8_t>(d[i], 2);
          continue;
        }
        const float off = glm::dot(g.normal[i], g.position[j] - g.position[i]);
        if (off > tau) d[i] = 1;
        else if (off < -tau && d[i] == 0) d[i] = 2;
      }
    }
  return d;
}

// Marks every pixel within `reach` pixels (a square) of a pixel where `source` holds: along each row, then
// along each column of that.
std::vector<std::uint8_t> dilate(const std::vector<std::uint8_t>& source, int w, int h, int reach) {
  // One line of `length` pixels, pixel k at index(k): marks in `to` what lies within reach of a mark in `from`.
  const auto line = [reach](const std::vector<std::uint8_t>& from, std::vector<std::uint8_t>& to, int length,
                            const auto& index) {
    int last = -2 * reach - 1;
    for (int k = 0; k < length; ++k) {
      if (from[index(k)]) last = k;
      if (k - last <= reach) to[index(k)] = 1;
    }
    last = length + 2 * reach + 1;
    for (int k = length - 1; k >= 0; --k) {
      if (from[index(k)]) last = k;
      if (last - k <= reach) to[index(k)] = 1;
    }
  };
  const auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x); };
  std::vector<std::uint8_t> rows(source.size(), 0), out(source.size(), 0);
  for (int y = 0; y < h; ++y) line(source, rows, w, [&](int x) { return at(x, y); });
  for (int x = 0; x < w; ++x) line(rows, out, h, [&](int y) { return at(x, y); });
  return out;
}

// The objects' box without the flat meshes (the ground, a receiver): the camera frames what casts occlusion,
// so that a radius spans enough pixels.
Bounds objects_bounds(const Scene& scene) {
  Bounds all;
  for (const Mesh& mesh : scene.meshes) {
    Bounds b;
    for (const glm::vec3& p : mesh.positions) b.extend(p);
    if (!b.empty() && b.max.y - b.min.y > kFlatMesh) all.extend(b);
  }
  return all.empty() ? scene.bounds() : all;
}

std::uint8_t grey(double v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5); }

// The AO (left) and the truth (right) side by side, top row first; in the AO half, halo pixels red.
std::vector<std::uint8_t> side_by_side(const GBuffer& g, const std::vector<float>& ao, const AoTruth& t,
                                       const std::vector<std::uint8_t>& halo) {
  const int w = g.width, h = g.height;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(2 * w) * h * 4, 255);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const std::size_t row = static_cast<std::size_t>(h - 1 - y) * 2 * w;
      std::uint8_t* a = &rgba[4 * (row + x)];
      std::uint8_t* b = &rgba[4 * (row + w + x)];
      a[0] = a[1] = a[2] = grey(ao[i]);
      if (halo[i]) a[1] = a[2] = 0;
      b[0] = b[1] = b[2] = t.valid[i] ? grey(t.open[i]) : 255;
    }
  return rgba;
}

// The figures of one frame against its truth; `halo` marks the pixels counted as halo (for the picture).
AoFigures tally(const GBuffer& g, const std::vector<float>& ao, const AoTruth& truth, float radius,
                std::vector<std::uint8_t>& halo) {
  const int w = g.width, h = g.height;
  const auto edge = discontinuities(g, radius);
  std::vector<std::uint8_t> any_edge(edge.size()), far_edge(edge.size());
  for (std::size_t i = 0; i < edge.size(); ++i) {
    any_edge[i] = edge[i] != 0 || !g.covered[i];
    far_edge[i] = edge[i] == 1;
  }
  const auto near_edge = dilate(any_edge, w, h, kInteriorMargin);
  const auto halo_band = dilate(far_edge, w, h, kHaloReach);
  AoFigures f;
  f.truth_seconds = truth.seconds;
  f.rays = truth.rays;
  double sum = 0.0, signed_sum = 0.0, dark_ao = 0.0, dark_truth = 0.0;
  halo.assign(edge.size(), 0);
  for (std::size_t i = 0; i < edge.size(); ++i) {
    if (!truth.valid[i] || !std::isfinite(ao[i])) continue;
    const double err = static_cast<double>(ao[i]) - truth.open[i];
    if (!near_edge[i]) {
      sum += std::abs(err);
      signed_sum += err;
      ++f.interior;
      if (truth.open[i] >= kOpenTruth) {
        f.open_error += std::abs(err);
        ++f.open;
      } else if (truth.open[i] < kOccludedTruth) {
        f.occluded_error += std::abs(err);
        dark_ao += 1.0 - ao[i];
        dark_truth += 1.0 - truth.open[i];
        ++f.occluded;
      }
    }
    if (far_edge[i]) ++f.edges;
    if (halo_band[i] && truth.open[i] >= kHaloOpenTruth && err < -kHaloDrop) {
      halo[i] = 1;
      ++f.halo_pixels;
    }
  }
  f.mean_error = f.interior ? sum / static_cast<double>(f.interior) : 1.0;
  f.mean_signed = f.interior ? signed_sum / static_cast<double>(f.interior) : 0.0;
  f.open_error = f.open ? f.open_error / static_cast<double>(f.open) : 1.0;
  f.occluded_error = f.occluded ? f.occluded_error / static_cast<double>(f.occluded) : 1.0;
  f.captured = dark_truth > 0.0 ? dark_ao / dark_truth : 0.0;
  f.halo_width = f.edges ? static_cast<double>(f.halo_pixels) / static_cast<double>(f.edges) : 0.0;
  return f;
}

// The four criteria of one frame, each with what to change when it fails.
void add_case_criteria(CheckResult& result, const AoCase& c, const AoFigures& f) {
  result.criteria.push_back(
      {c.tag + ".open_error", f.open_error, Criterion::kAtMost, kOpenErrorLimit,
       "mean |AO - AO truth| over interior pixels the truth sees open: the AO truth's own error (kAoTruthError)",
       "open surfaces (a floor with nothing near it) are drawn darker than open: the samples must lie in the "
       "hemisphere above the surface (turned around the normal by a frame from Gram-Schmidt, in view space like "
       "p), a sample is hidden only when the surface is NEARER the camera than the sample by more than bias, "
       "and you return the open share, not the occluded one."});
  result.criteria.push_back(
      {c.tag + ".darkening_share", f.captured, Criterion::kAtLeast, kMinDarkeningShare,
       "the AO's darkening over the truth's, over interior pixels the truth sees occluded; the solution's lowest "
       "measured, with a margin (INSTRUCTOR.md)",
       "creases and contacts are not darkened enough: count a sample as hidden when the depth buffer's surface is "
       "in front of it, and weigh a near occluder fully (the range check must only weigh down occluders much "
       "farther than radius)."});
  result.criteria.push_back(
      {c.tag + ".darkening_share_cap", f.captured, Criterion::kAtMost, kMaxDarkeningShare,
       "the same share, at most: the solution's highest measured, with a margin (INSTRUCTOR.md)",
       "creases are darkened over too wide a reach: the kernel's samples must be scaled by radius, and kept as the "
       "kernel gives them (nearer the centre)."});
  result.criteria.push_back(
      {c.tag + ".halo_width_px", f.halo_width, Criterion::kAtMost, kHaloWidthLimit,
       "mean width (pixels) of false dark halos on the far side of depth discontinuities; the solution's worst "
       "measured, twice (INSTRUCTOR.md)",
       "dark halos around the objects on surfaces far behind them: an occluder much farther from the point "
       "than the radius must not count (the range check)."});
}

AoFigures grade_case(CheckContext& ctx, CheckResult& result, const Oracle& oracle, const ParamSet& params,
                     const AoCase& c) {
  FrameRequest request;
  request.camera = OrbitCamera::framing(objects_bounds(ctx.scene()), c.yaw, c.pitch);
  request.width = kWidth;
  request.height = kHeight;
  request.gbuffer = true;
  ctx.renderer.render(params, request);
  const GBuffer g = ctx.renderer.read_gbuffer();
  const std::vector<float> ao = ctx.renderer.read_ao(true);
  const AoTruth truth = evaluate_ao(oracle, g, c.radius);
  const int w = g.width, h = g.height;
  std::vector<std::uint8_t> halo;
  const AoFigures f = tally(g, ao, truth, c.radius, halo);
  const std::string name = "lab17_" + c.tag + "_" + impl_name(ctx.impl);
  if (!ctx.out_dir.empty()) {
    const auto final_path = ctx.out_dir / (name + "_final.png");
    const auto ao_path = ctx.out_dir / (name + "_ao_vs_truth.png");
    write_png(final_path, w, h, ctx.renderer.read_color());
    write_png(ao_path, 2 * w, h, side_by_side(g, ao, truth, halo));
    result.images.push_back(final_path.string());
    result.images.push_back(ao_path.string());
  }
  result.metrics[c.tag] = {{"scene", c.scene},
                           {"yaw_deg", c.yaw},
                           {"pitch_deg", c.pitch},
                           {"radius", c.radius},
                           {"mean_error", f.mean_error},
                           {"mean_signed_error", f.mean_signed},
                           {"interior_pixels", f.interior},
                           {"open_error", f.open_error},
                           {"open_pixels", f.open},
                           {"occluded_error", f.occluded_error},
                           {"occluded_pixels", f.occluded},
                           {"captured_darkening", f.captured},
                           {"far_edge_pixels", f.edges},
                           {"halo_pixels", f.halo_pixels},
                           {"halo_width_px", f.halo_width},
                           {"truth_rays", f.rays},
                           {"truth_ms", f.truth_seconds * 1000.0}};
  std::printf("    %-10s open %.4f (%ld px) occluded %.4f (%ld px) captured %.4f\n", c.tag.c_str(), f.open_error, f.open,
              f.occluded_error, f.occluded, f.captured);
  std::printf("    %-10s AO mean error %.4f (signed %+.4f, %ld px), halo width %.3f px (%ld / %ld), truth %.2f s %llu rays\n",
              c.tag.c_str(), f.mean_error, f.mean_signed, f.interior, f.halo_width, f.halo_pixels, f.edges,
              f.truth_seconds, static_cast<unsigned long long>(f.rays));
  add_case_criteria(result, c, f);
  return f;
}

void check_ssao(CheckContext& ctx, CheckResult& result) {
  ParamSet params = ctx.params();
  params.set(param::view_debug_quad, false);
  ctx.use(ctx.hooks());
  std::vector<AoCase> cases = {{"lab", "default", 30.0f, 30.0f, static_cast<float>(params.get(param::ssao_radius))}};
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> yaw(60.0f, 330.0f), pitch(20.0f, 45.0f), radius(kHeldOutMinRadius, kHeldOutMaxRadius);
  const char* scenes[2] = {"default", "default"};
  for (int k = 0; k < 2; ++k) {
    AoCase c{"held_out_" + std::to_string(k + 1), scenes[k], std::round(yaw(rng)), std::round(pitch(rng)),
             std::round(radius(rng) * 20.0f) / 20.0f};
    cases.push_back(c);
    result.conditions.push_back({{"tag", c.tag}, {"scene", c.scene}, {"yaw_deg", c.yaw}, {"pitch_deg", c.pitch},
                                 {"radius", c.radius}});
  }
  std::string scene_name;
  std::unique_ptr<Oracle> oracle;
  for (const AoCase& c : cases) {
    if (c.scene != scene_name) {
      ctx.use_scene_named(c.scene);
      ctx.renderer.set_scene(ctx.scene());
      oracle = std::make_unique<Oracle>(ao_occluders(ctx.renderer.scene()));
      scene_name = c.scene;
    }
    ParamSet p = params;
    p.set(param::ssao_radius, c.radius);
    grade_case(ctx, result, *oracle, p, c);
  }
  ctx.use_default_scene();
}

// Self-occlusion's speckle is faint (positions are stored as floats): seen from the framed camera it
// changes 0.27 % of a 1280x720 frame against "tuned", below what a lecture hall sees; close over the big
// box's top and the floor beside it (kShadowEdgeCamera's view at a 15-degree field) it changes 3.49 %.
// Banding from kShadowEdgeCamera: 5.78 % (0.63 % framed). Measured as cli.preset_contrast measures.
constexpr const char* kCloseOverTheBoxCamera = "eye=-4.6,2.2,1.8 target=-3.6,0,-0.4 fov=15";

}  // namespace

Lab SHADOWLAB_LAB_MAKER() {
  Lab lab;
  lab.title = "Screen-space ambient occlusion";
  lab.summary = "The shadows of indirect light: the open share of the hemisphere around each point, from the depth buffer.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  // The student's SSAO's sliders, then the renderer's other method beside it (GTAO, ssao.method).
  lab.params = ssao_param_specs();
  for (ParamSpec& spec : ao_method_param_specs()) lab.params.push_back(spec);
  for (ParamSpec& spec : lab.params)
    if (spec.key == param::ssao_radius.key()) spec.default_value = kRadius;
  // In the window a preset sets only its own keys over the current values (apply_preset), and Page Down
  // steps through these in order: each SSAO preset sets every ssao.* key the lab's text describes, "tuned"'s
  // values but those that provoke its artefact, so that it shows that artefact alone whatever came before.
  lab.presets = {
      {"halos", "A large radius without the range check: the boxes and the sphere darken the floor far behind them.",
       {{"ssao.radius", "2"}, {"ssao.range_check", "0"}, {"ssao.method", "ssao"}, {"ssao.samples", "32"},
        {"ssao.bias", "0.025"}, {"ssao.blur", "1"}, {"ssao.noise", "1"}},
       {.provokes = "halos", .fixed_by = "tuned"}},
      {"self-occlusion", "Bias 0 and no blur: samples lying almost in the surface's own plane are compared with the surface's own "
       "depths, and some count as hidden: a faint speckle on flat surfaces (faint here: the positions are stored as floats).",
       {{"ssao.bias", "0"}, {"ssao.blur", "0"}, {"ssao.method", "ssao"}, {"ssao.radius", "0.5"}, {"ssao.samples", "32"},
        {"ssao.range_check", "1"}, {"ssao.noise", "1"}},
       {.provokes = "self-occlusion", .fixed_by = "tuned"}, {.camera = kCloseOverTheBoxCamera}},
      {"banding", "No noise, no blur, 8 samples: every pixel uses the same few sample directions, and bands show.",
       {{"ssao.noise", "0"}, {"ssao.blur", "0"}, {"ssao.samples", "8"}, {"ssao.method", "ssao"}, {"ssao.radius", "0.5"},
        {"ssao.bias", "0.025"}, {"ssao.range_check", "1"}},
       {.provokes = "banding", .fixed_by = "tuned"}, {.camera = kShadowEdgeCamera}},
      {"noise without blur", "The noise's rotations without the blur: the 4 x 4 pattern shows.",
       {{"ssao.blur", "0"}, {"ssao.method", "ssao"}, {"ssao.radius", "0.5"}, {"ssao.samples", "32"}, {"ssao.bias", "0.025"},
        {"ssao.range_check", "1"}, {"ssao.noise", "1"}}},
      {"tuned", "The lab's defaults: radius 0.5, 32 samples, bias 0.025, range check, noise and blur on.",
       {{"ssao.method", "ssao"}, {"ssao.radius", "0.5"}, {"ssao.samples", "32"}, {"ssao.bias", "0.025"},
        {"ssao.range_check", "1"}, {"ssao.blur", "1"}, {"ssao.noise", "1"}}},
      {"gtao", "The renderer's horizon-based AO (GTAO, 4 directions x 8 steps) in place of SSAO: darker, closer to the "
       "ray-cast truth in the creases, for less than the lab's own SSAO (32 samples, blurred) costs (README, the AO front).",
       {{"ssao.method", "gtao"}, {"ssao.gtao_directions", "4"}, {"ssao.gtao_steps", "8"}}},
  };
  lab.offered_includes = {};
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.light = LightType::Directional;
    hooks.ssao = true;
    hooks.includes["lab/ssao.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_ssao;
  return lab;
}

}  // namespace shadowlab
