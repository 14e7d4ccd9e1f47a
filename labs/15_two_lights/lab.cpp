// Lab 15: two shadowed lights, the sun and a flashlight (the Polish lab's ship with its reflector).
// Demonstrates: N lights in one frame, each with its own map and technique (the sun's ortho depth map, the
// flashlight's perspective one, core/flashlight.h), each light's Lambert term multiplied by its OWN
// shadow term; the flashlight's map redrawn alone while it moves. The student writes combine_lights.
// Check: per light and combined. Three frames per condition: the sun alone (flashlight.intensity 0), the
// flashlight alone (sun.intensity 0) and both; in each the direct light the combination returned (the
// G-buffer's visibility under SHADOWED_LIGHTS) against the oracle's truth for each light (Embree, cast toward the
// sun and toward the flashlight) times its Lambert term, on pixels in the interior of both lights' truths.
// Conditions: the lab's own (node at flashlight.phase), and held out from the seed: the node elsewhere on its
// circle with other intensities and the flashlight on the camera seen from another side.
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "grading/check.h"
#include "grading/lab.h"
#include "core/flashlight.h"
#include "core/image_io.h"

namespace shadowlab {

namespace {

constexpr const char* kExercise = SHADOWLAB_LAB_FOLDER "/exercise.glsl";
constexpr const char* kSolution = "shaders/shadow/combine_lights.glsl";

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
constexpr Frame kFrames[] = {{"sun", true, false}, {"flashlight", false, true}, {"combined", true, true}};

const char* frame_advice(const std::string& frame) {
  if (frame == "sun") return "with the flashlight off the sun alone must light the scene: the sun's Lambert term times the sun's own shadow term.";
  if (frame == "flashlight")
    return "with the sun off the flashlight alone must light the scene: its Lambert term times ITS OWN shadow term "
           "(flash_shadow), not the sun's.";
  return "each light's term times its own shadow term, and the two added: light from both where both reach.";
}

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
                               frame_advice(frame.name)});
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

void check_two_lights(CheckContext& ctx, CheckResult& result) {
  const Features hooks = ctx.hooks();
  std::vector<Condition> conditions = {{"node", {}, 30.0f}};
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  char text[64];
  Condition held{"held_out_node", {}, 30.0f + 60.0f * unit(rng)};
  std::snprintf(text, sizeof text, "%.1f", 150.0 + 100.0 * unit(rng));
  held.sets.push_back({"flashlight.phase", text});
  std::snprintf(text, sizeof text, "%.2f", 0.5 + 0.7 * unit(rng));
  held.sets.push_back({"sun.intensity", text});
  std::snprintf(text, sizeof text, "%.2f", 0.5 + 0.9 * unit(rng));
  held.sets.push_back({"flashlight.intensity", text});
  std::snprintf(text, sizeof text, "%.1f", 25.0 + 40.0 * unit(rng));
  held.sets.push_back({"light.azimuth", text});
  Condition camera{"held_out_camera", {{"flashlight.mount", "camera"}}, -40.0f - 50.0f * unit(rng)};
  for (Condition* c : {&held, &camera}) {
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
  lab.summary = "Each light's term times its own shadow term: an ortho map for the sun, a perspective one for the flashlight.";
  lab.exercise_files = {kExercise};
  lab.solution_files = {kSolution};
  lab.params = flashlight_param_specs();
  lab.presets = {
      {"moving node", "The node circles the scene: only the flashlight's map is drawn again (the panel's counters).",
       {{"flashlight.animate", "true"}, {"flashlight.mount", "node"}}},
      {"flashlight on the camera", "The flashlight shines from the eye: orbit and watch its map follow.",
       {{"flashlight.mount", "camera"}, {"flashlight.animate", "false"}}},
      {"flashlight alone", "The sun off: only the flashlight's light and shadows.", {{"sun.intensity", "0"}}},
      {"sun alone", "The flashlight off: the one-light picture of the earlier labs.", {{"flashlight.intensity", "0"}}},
  };
  lab.offered_includes = {};
  lab.make_hooks = [](const SlotFiles& files) {
    Features hooks;
    hooks.light = LightType::Directional;
    hooks.lights = {flashlight_spec()};  // the sun is the frame's light, the flashlight the list's one entry
    hooks.includes["lab/combine.glsl"] = files.at(0).string();
    return hooks;
  };
  lab.check = check_two_lights;
  return lab;
}

}  // namespace shadowlab
