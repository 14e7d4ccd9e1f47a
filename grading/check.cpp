#include "grading/check.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "core/platform.h"
#include "grading/cpp_exercise.h"
#include "core/image_io.h"

namespace shadowlab {

bool CheckResult::passed() const {
  if (!error.empty() || criteria.empty()) return false;  // a check that grades nothing cannot pass
  for (const auto& c : criteria)
    if (!c.passed()) return false;
  return true;
}

const char* status_name(CheckStatus status) {
  switch (status) {
    case CheckStatus::Passed: return "passed";
    case CheckStatus::Failed: return "failed";
    case CheckStatus::CompileError: return "compile_error";
    case CheckStatus::Crashed: return "crashed";
    case CheckStatus::TimedOut: return "timed_out";
    case CheckStatus::GraderError: return "grader_error";
  }
  return "grader_error";
}

CheckStatus CheckResult::status() const {
  if (!error.empty()) return students_error ? students_failure : CheckStatus::GraderError;
  return passed() ? CheckStatus::Passed : CheckStatus::Failed;
}

nlohmann::json CheckResult::to_json() const {
  nlohmann::json thresholds = nlohmann::json::object();
  nlohmann::json graded = metrics;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : criteria) {
    const char* side = c.direction == Criterion::kAtMost ? "max" : "min";
    thresholds[c.metric] = {{side, c.limit}, {"why", c.why}};
    if (c.basis != Criterion::kLabLimit)
      thresholds[c.metric]["basis"] = c.basis == Criterion::kSolutionValue ? "solution" : "not_measurable";
    graded[c.metric] = c.value;
    list.push_back({{"metric", c.metric}, {"value", c.value}, {side, c.limit}, {"passed", c.passed()},
                    {"sentence", c.explain()}, {"why", c.why}});
  }
  nlohmann::json j = {{"lab", lab},         {"slug", slug},         {"impl", impl_name(impl)},
                      {"status", status_name(status())},             {"passed", passed()},
                      {"metrics", graded},  {"thresholds", thresholds}, {"criteria", list},
                      {"seed", seed},       {"conditions", conditions}, {"seconds", seconds}};
  j["parameters"] = parameters;
  if (!submission.empty()) j["submission"] = submission;
  if (!images.empty()) j["images"] = images;
  if (!error.empty()) j["error"] = error;
  if (!warnings.empty()) j["warnings"] = warnings;
  if (!notes.empty()) j["notes"] = notes;
  return j;
}

namespace {

std::string format(const char* fmt, double a, double b = 0.0) {
  char s[256];
  std::snprintf(s, sizeof s, fmt, a, b);
  return s;
}

// "k3.acne_rate" -> ("k3", "acne_rate"): the part before the last dot names the case a lab measured.
std::pair<std::string, std::string> split_metric(const std::string& metric) {
  const auto dot = metric.rfind('.');
  if (dot == std::string::npos) return {"", metric};
  return {metric.substr(0, dot), metric.substr(dot + 1)};
}

// The measured fact as a sentence, the usual advice for the metric (a lab's own advice wins), and the unit
// the sentence states the value in (declared once here: the limit is said in the same unit).
struct Description {
  std::string sentence, usual;
  double scale = 1.0;     // the value as the sentence states it: value x scale
  std::string unit = "";  // after the number: "%", "x", "deg"; empty: a plain number
  bool usual_states_limit = false;  // the usual advice only repeats the limit: no hint of its own
  bool named_only = false;  // no sentence written for this metric: "name = value"
};
constexpr double kPercent = 100.0;

Description describe(const Criterion& c, const std::string& name) {
  const double v = c.value;
  if (name == "lit_error")
    return {format("lit surfaces are drawn %.2f %% darker than the truth on average (acne or a partial shadow)", 100 * v),
            "raise the bias, or make it grow with the slope; and a lit surface must come out exactly 1.", kPercent, "%"};
  if (name == "shadow_error")
    return {format("shadowed surfaces get %.2f %% of the light on average (leaks, peter-panning)", 100 * v),
            "lower the bias or check the depth comparison; a shadowed surface must come out 0.", kPercent, "%"};
  if (name == "penumbra_error")
    return {format("the penumbra is off by %.3f on average from the share of the light each point sees", v),
            "the soft edge must widen with the light's size and the blocker-to-receiver distance, and narrow to hard as the light shrinks."};
  if (name == "graded_pixels")
    return {format("the view has %.0f lit or shadowed pixels away from shadow edges", v),
            "not measurable: the scene shows too little shadow to grade anything. Grade on a scene with shadows."};
  if (name == "acne_rate" || name == "acne_rate_all")
    return {format("%.2f %% of lit pixels show acne (drawn in shadow)", 100 * v), "raise the bias, or make it grow with the slope.", kPercent, "%"};
  if (name == "leak_rate" || name == "leak_rate_all")
    return {format("%.2f %% of shadowed pixels are drawn lit (light leaks, peter-panning)", 100 * v),
            "lower the bias or check the depth comparison.", kPercent, "%"};
  if (name == "bleeding_rate")
    return {format("%.2f %% of shadowed pixels show light bleeding", 100 * v), "cut the low tail of Chebyshev's bound (raise delta).", kPercent, "%"};
  if (name == "bleeding_ratio_to_unfixed")
    return {format("light bleeding is %.0f %% of what it is without your fix", 100 * v),
            format("it must drop to %.0f %% or less.", 100 * c.limit), kPercent, "%", true};
  if (name == "error_ratio_fitted_to_fixed")
    return {format("the fitted box's error (acne + leak) is %.2f x the fixed box's", v), "fit the box tighter around the scene's bounds.", 1.0, "x"};
  if (name == "non_finite_directions")
    return {format("%.0f light directions gave a matrix with NaN or Inf", v), "pick another up vector when the light looks along +-Y."};
  if (name == "corners_outside")
    return {format("%.0f corners of the scene's box fall outside the light's box", v), "the box must enclose every corner."};
  if (name == "loose_directions")
    return {format("%.0f light directions gave a box looser than needed", v), "take min and max of the corners in light space."};
  if (name == "interior_agreement")
    return {format("%.2f %% of pixels away from edges agree with the ray-cast truth", 100 * v),
            format("needs %.2f %%.", 100 * c.limit), kPercent, "%", true};
  if (name == "max_first_moment_error" || name == "max_second_moment_error")
    return {format(name == "max_first_moment_error" ? "the stored E[z] is off by up to %.2g" : "the stored E[z^2] is off by up to %.2g", v),
            "write depth and depth squared (with the slope term) into the moments."};
  if (name == "max_texel_error")
    return {format("the blurred moments differ from an exact Gaussian by up to %.2g", v),
            "normalise the weights and sample at the right offsets."};
  if (name.find("negative_variance") != std::string::npos)
    return {format("%.0f texels have a negative variance", v), "E[z^2] - E[z]^2 must not go below the minimum variance."};
  if (name.find("non_finite") != std::string::npos) return {format("%.0f values are NaN or Inf", v), "no NaN or Inf may come out."};
  if (name == "orientation")
    return {format("the quad is turned up to %.2f deg away from the upright quad facing the light", v),
            "turn the quad about the vertical toward the light.", 1.0, "deg"};
  if (name == "size")
    return {format("the quad's sides are up to %.1f %% off the tree's size, or not at a right angle", 100 * v),
            "make the sides the tree's width and height, at a right angle.", kPercent, "%"};
  if (name == "follows_camera") {
    if (c.metric.starts_with("shadow_map"))
      return {format("%.2f %% of the shadow map's texels change when only the camera moves", 100 * v),
              "the shadow must not depend on the camera.", kPercent, "%"};
    return {format("the shadow pass's quad moves by up to %.3g units when only the camera moves", v),
            "the shadow must not depend on the camera.", 1.0, "units"};
  }
  if (name.ends_with("_mismatch"))
    return {format("%.2f %% of the probe's cases differ from the reference", 100 * v), "compare your function with the lab's text.", kPercent, "%"};
  const bool whole = v == static_cast<long long>(v) && c.limit == static_cast<long long>(c.limit);
  return {name + format(whole ? " = %.0f" : " = %.4g", v), "", 1.0, "", false, true};
}

}  // namespace

std::string Criterion::explain() const {
  const auto [tag, name] = split_metric(metric);
  const Description d = describe(*this, name);
  const std::string& sentence = d.sentence;
  const std::string& fix = advice.empty() ? d.usual : advice;
  const char* op = direction == kAtMost ? "<=" : ">=";
  const bool whole = limit == static_cast<long long>(limit) && std::abs(limit) >= 1;
  std::string s = sentence + (tag.empty() ? "" : " [" + tag + "]");
  if (passed()) return s + ".";
  char needs[64];
  std::snprintf(needs, sizeof needs, whole ? " (needs %s %.0f)" : " (needs %s %.4g)", op, limit);
  return s + needs + (fix.empty() ? "." : ": " + fix);
}

std::string Criterion::headline() const {
  const auto [tag, name] = split_metric(metric);
  const Description d = describe(*this, name);
  std::string s = d.sentence;
  if (d.named_only) {  // the metric's name in words ("growth_at_steep_slope" -> "growth at steep slope is 0")
    s = name;
    std::replace(s.begin(), s.end(), '_', ' ');
    const bool whole = value == static_cast<long long>(value);
    s += format(whole ? " is %.0f" : " is %.4g", value);
  }
  if (!s.empty()) s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
  // A number and its unit stay on one line where the panel wraps: a no-break space (U+00A0) between them.
  const std::string nbsp = "\u00a0";
  for (std::size_t at = s.find(" %"); at != std::string::npos; at = s.find(" %", at + nbsp.size())) s.replace(at, 1, nbsp);
  const double shown = limit * d.scale;
  char number[64];
  std::snprintf(number, sizeof number, shown == static_cast<long long>(shown) && std::abs(shown) < 1e9 ? "%.0f" : "%.3g", shown);
  s += direction == kAtMost ? "; at most " : "; at least ";
  s += number + (d.unit.empty() ? "" : nbsp + d.unit) + (direction == kAtMost ? " allowed" : " needed");
  if (!tag.empty()) s += " (" + tag + ")";
  return s + ".";
}

std::string Criterion::hint() const {
  if (!advice.empty()) return advice;
  const Description d = describe(*this, split_metric(metric).second);
  return d.usual_states_limit ? "" : d.usual;
}

void grade_lab_and_held_out_lights(CheckContext& ctx, CheckResult& result, const std::string& prefix,
                                   const std::string& tag, const ParamSet& params, const ParamSet& held_out_params,
                                   const std::vector<HeldOutRange>& ranges, const HardLimits& limits) {
  const Features features = ctx.hooks();
  const std::string impl = impl_name(ctx.impl);
  const auto m = ctx.measure(params, features, prefix + "_" + tag + "_" + impl);
  grade_hard_shadow(result, tag, m.metrics, limits);
  result.metrics[tag]["render_ms"] = m.render_ms;
  result.metrics[tag]["oracle_ms"] = m.oracle_ms;
  for (const auto& c : draw_directional_cases(ctx, ranges)) {
    const auto h = ctx.measure(c.apply(ctx, held_out_params), features, prefix + "_" + c.tag + "_" + impl);
    grade_hard_shadow(result, c.tag, h.metrics, limits);
    result.conditions.push_back(c.to_json());
  }
  ctx.use_default_scene();
}

void grade_hard_shadow(CheckResult& result, const std::string& tag, const Metrics& m, const HardLimits& limits) {
  result.metrics[tag] = to_json(m);
  result.criteria.push_back({tag + ".lit_error", m.lit_error, Criterion::kAtMost, limits.lit_error, limits.why, limits.lit_advice});
  result.criteria.push_back(
      {tag + ".shadow_error", m.shadow_error, Criterion::kAtMost, limits.shadow_error, limits.why, limits.shadow_advice});
  if (m.soft)
    result.criteria.push_back({tag + ".penumbra_error", m.penumbra_error, Criterion::kAtMost, limits.penumbra_error,
                               soft_truth_why(limits.penumbra_error), limits.penumbra_advice});
  require_measurable(result, tag, m);
}

std::string soft_truth_why(double limit) {
  char s[256];
  std::snprintf(s, sizeof s,
                "mean error over the penumbra <= %.3g against the soft truth (%d x %d samples of the light's disk per "
                "pixel; its own error: mean %.4f, worst pixel %.3f)",
                limit, kSoftTruthStrata, kSoftTruthStrata, kSoftTruthMeanError, kSoftTruthWorstError);
  return s;
}

void require_measurable(CheckResult& result, const std::string& tag, const Metrics& m) {
  const double seen = static_cast<double>(std::min(m.interior_lit, m.interior_shadowed));
  result.criteria.push_back({tag + ".graded_pixels", seen, Criterion::kAtLeast, kMinGradedPixels,
                             "fewer lit or shadowed interior pixels grade nothing", ""});
}

CheckContext::CheckContext(Renderer& r, const Lab& l, Impl i, const Scene& default_scene, std::filesystem::path out)
    : renderer(r), lab(l), impl(i), out_dir(std::move(out)), graded(l.files(i)), default_scene_(&default_scene), scene_(&default_scene) {}

void CheckContext::grade_submission(const std::filesystem::path& folder) {
  impl = Impl::Exercise;
  submission = folder;
  graded.clear();
  for (const auto& file : lab.exercise_files) {
    const auto path = std::filesystem::absolute(folder / file);
    // Not the grader's fault, and not to be graded as the stock file: the student's answer is missing.
    if (!std::filesystem::is_regular_file(path))
      throw BuildError(file + ": not in the submission (lay it out like the project: " + file + ")");
    graded.push_back(path);
  }
}

Features CheckContext::hooks_with_only(std::size_t slot) const {
  SlotFiles files = lab.files(Impl::Solution);
  files.at(slot) = graded.at(slot);
  return lab.hooks_for(files);
}

void CheckContext::use(const Features& hooks) {
  if (!renderer.set_features(hooks)) throw BuildError(renderer.shader_error());
}

ParamSet CheckContext::params() const {
  ParamSet p = lab_params(lab);
  for (const auto& a : assignments) p.apply_assignment(a);
  return p;
}

void CheckContext::use_scene(const Scene& scene) {
  owned_scene_ = std::make_unique<Scene>(scene);
  scene_ = owned_scene_.get();
  ++scene_generation_;
  oracle_.reset();
}

void CheckContext::use_default_scene() {
  if (scene_ == default_scene_) return;
  scene_ = default_scene_;
  owned_scene_.reset();
  ++scene_generation_;
  oracle_.reset();
}

void CheckContext::use_scene_named(const std::string& name) {
  if (name == "default") return use_default_scene();
  if (name == "stacked") return use_scene(make_stacked_occluders_scene());
  throw std::invalid_argument("no built-in scene named " + name);
  oracle_.reset();
}

const Oracle& CheckContext::oracle() {
  // The scene as the renderer draws it (with the ground plane it adds to a scene without one, and the
  // scene.blend_casts choice), once it has been uploaded; the same triangles the shadow map holds.
  if (!oracle_) oracle_ = std::make_unique<Oracle>(uploaded_generation_ == scene_generation_ ? renderer.scene() : *scene_);
  return *oracle_;
}

OracleLight oracle_light(const Renderer& renderer) {
  OracleLight light;
  if (renderer.light_type() != LightType::Directional) {
    light.positional = true;
    light.position = renderer.light_position();
    const int size = std::max(renderer.shadow_map_size(), 1);
    // The angle one texel spans at the map's centre: a spot's map covers 2 tan(cone) over `size` texels,
    // each 90-degree cube face 2 tan(45 deg) = 2.
    const float extent = renderer.light_type() == LightType::Spot
                             ? 2.0f * std::tan(glm::radians(renderer.spot_cone_deg()))
                             : 2.0f;
    light.texel_angle = std::atan(extent / static_cast<float>(size));
    light.image_x = renderer.light_view().image_x;
    light.image_y = renderer.light_view().image_y;
    return light;
  }
  light.positional = false;
  light.to_light = renderer.to_light();
  light.image_x = renderer.light_view().image_x;
  light.image_y = renderer.light_view().image_y;
  // The light's box is fitted in the local frame, scaled with the scene: the oracle works in the scene's own.
  light.texel_world_size = static_cast<float>(renderer.light_view().world_size.x / renderer.placement().scale /
                                              static_cast<double>(renderer.shadow_map_size()));
  return light;
}

double interior_agreement(const Metrics& m) {
  const double lit = static_cast<double>(m.interior_lit), shadowed = static_cast<double>(m.interior_shadowed);
  if (lit + shadowed <= 0.0) return 0.0;  // nothing graded agrees with nothing
  return 1.0 - (m.acne_rate * lit + m.leak_rate * shadowed) / (lit + shadowed);
}

OrbitCamera camera_looking_at(const glm::vec3& eye, const glm::vec3& target, float near_plane, float far_plane) {
  OrbitCamera cam;
  const glm::vec3 d = eye - target;
  cam.target = target;
  cam.distance = glm::length(d);
  cam.pitch_deg = glm::degrees(std::asin(d.y / cam.distance));
  cam.yaw_deg = glm::degrees(std::atan2(d.x, d.z));
  cam.near_plane = near_plane;
  cam.far_plane = far_plane;
  return cam;
}

CheckContext::Measurement CheckContext::measure(const ParamSet& params, const Features& hooks, const std::string& name,
                                                const Bounds* view, const BandSpec& band, int width, int height,
                                                const OrbitCamera* camera, const Oracle* truth_oracle) {
  using clock = std::chrono::steady_clock;
  Measurement m;
  use(hooks);
  if (uploaded_generation_ != scene_generation_) {
    renderer.set_scene(*scene_);
    uploaded_generation_ = scene_generation_;
  }
  FrameRequest request;
  request.camera = camera ? *camera : OrbitCamera::framing(view ? *view : scene_->bounds());
  request.width = width;
  request.height = height;
  request.gbuffer = true;
  const auto t0 = clock::now();
  renderer.render(params, request);
  m.visibility = renderer.read_visibility();
  GBuffer gbuffer = renderer.read_gbuffer();
  if (renderer.light_type() == LightType::Spot) {
    const float cos_graded = std::cos(glm::radians(renderer.spot_cone_deg() - kSpotConeMarginDeg));
    for (std::size_t i = 0; i < gbuffer.position.size(); ++i) {
      const glm::vec3 d = gbuffer.position[i] - renderer.light_position();
      if (gbuffer.covered[i] && glm::dot(glm::normalize(d), renderer.spot_direction()) < cos_graded) gbuffer.covered[i] = 0;
    }
  }
  const auto t1 = clock::now();
  const OracleLight light = oracle_light(renderer);
  auto same_light = [](const OracleLight& a, const OracleLight& b) {
    return a.positional == b.positional && a.to_light == b.to_light && a.position == b.position &&
           a.texel_world_size == b.texel_world_size && a.image_x == b.image_x && a.image_y == b.image_y &&
           a.texel_angle == b.texel_angle;
  };
  auto same_band = [](const BandSpec& a, const BandSpec& b) {
    return a.radius_texels == b.radius_texels && a.samples == b.samples && a.fixed_screen_pixels == b.fixed_screen_pixels &&
           a.grazing_n_dot_l == b.grazing_n_dot_l;
  };
  // A light with a size is graded against the visible fraction of its disk (soft_truth.h).
  const float size = renderer.light_size();
  if (truth_oracle) {
    m.truth = truth_oracle->evaluate(gbuffer, light, band);
    if (size > 0.0f) m.soft = evaluate_soft(*truth_oracle, gbuffer, light, size, kSoftTruthStrata);
  } else if (last_.scene_generation == scene_generation_ && same_light(last_.light, light) && same_band(last_.band, band) &&
      last_.size == size && last_.gbuffer.width == gbuffer.width && last_.gbuffer.height == gbuffer.height &&
      last_.gbuffer.covered == gbuffer.covered && last_.gbuffer.position == gbuffer.position &&
      last_.gbuffer.normal == gbuffer.normal) {
    m.truth = last_.truth;
    m.soft = last_.soft;
  } else {
    m.truth = oracle().evaluate(gbuffer, light, band);
    if (size > 0.0f) m.soft = evaluate_soft(oracle(), gbuffer, light, size, kSoftTruthStrata);
    last_ = {scene_generation_, gbuffer, light, band, m.truth, size, m.soft};
  }
  if (size > 0.0f) m.truth = soften(m.truth, m.soft);
  m.metrics = compare(m.truth, m.visibility);
  if (size > 0.0f) add_soft_metrics(m.metrics, m.soft, m.visibility);
  const auto t2 = clock::now();
  m.render_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  m.oracle_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  if (!out_dir.empty()) {
    const auto final_path = out_dir / (name + "_final.png");
    const auto diff_path = out_dir / (name + "_diff.png");
    write_png(final_path, width, height, renderer.read_color());
    // A sized light: the soft diff (the fraction in grey, turned red where drawn too dark, blue too light).
    write_png(diff_path, width, height,
              size > 0.0f ? soft_diff_image(m.soft, m.visibility) : diff_image(m.truth, m.visibility));
    images.push_back(final_path.string());
    images.push_back(diff_path.string());
  }
  return m;
}

nlohmann::json DirectionalCase::to_json() const {
  return {{"tag", tag}, {"scene", scene}, {"light_azimuth", azimuth}, {"light_elevation", elevation}, {"map_size", map_size}};
}

ParamSet DirectionalCase::apply(CheckContext& ctx, const ParamSet& params) const {
  ctx.use_scene_named(scene);
  ParamSet p = params;
  p.set("light.azimuth", azimuth);
  p.set("light.elevation", elevation);
  p.set_from_string("shadow.map_size", map_size);
  return p;
}

std::vector<DirectionalCase> draw_directional_cases(CheckContext& ctx, const std::vector<HeldOutRange>& ranges) {
  constexpr float kHeldOutAzimuthSpread = 75.0f;
  const float base_azimuth = ctx.params().get(param::light_azimuth);
  std::mt19937 rng = ctx.held_out_rng();
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  auto pick = [&](const std::vector<std::string>& list) {
    return list.at(std::uniform_int_distribution<std::size_t>(0, list.size() - 1)(rng));
  };
  std::vector<DirectionalCase> cases;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    DirectionalCase c;
    c.tag = "held_out_" + std::to_string(i + 1);
    c.elevation = ranges[i].min_elevation + (ranges[i].max_elevation - ranges[i].min_elevation) * unit(rng);
    // Within 75 degrees of the lab's azimuth: from farther round the check's camera sees the shadows from
    // behind the objects that cast them, and too few shadowed pixels remain to grade (seen at 270-310
    // degrees from the default 35).
    c.azimuth = std::fmod(base_azimuth + kHeldOutAzimuthSpread * (2.0f * unit(rng) - 1.0f) + 360.0f, 360.0f);
    c.map_size = pick(ranges[i].map_sizes);
    c.scene = pick(ranges[i].scenes);
    cases.push_back(c);
  }
  return cases;
}

namespace {

CheckResult grade_on(Renderer& renderer, const Lab& lab, const Scene& scene, const CheckRun& run) {
  CheckResult result;
  result.lab = lab.number;
  result.slug = lab.slug;
  result.impl = run.impl;
  result.seed = run.seed;
  result.submission = run.submission.string();
  const auto start = std::chrono::steady_clock::now();
  try {
    CheckContext ctx(renderer, lab, run.impl, scene, run.out_dir);
    if (!run.submission.empty())
      ctx.grade_submission(run.submission);
    else if (run.impl == Impl::Exercise)
      result.notes = ctx.grade_edited_cpp_files();
    ctx.seed = run.seed;
    ctx.assignments = run.assignments;
    result.parameters = ctx.params().to_json();
    ctx.use(ctx.hooks());  // the graded files first: their errors and warnings, before any grading
    result.warnings = renderer.shader_warnings();
    if (!lab.check) throw std::runtime_error("lab " + std::to_string(lab.number) + " has no check");
    lab.check(ctx, result);
    result.images = ctx.images;
  } catch (const ExerciseError& e) {  // a submitted C++ exercise that does not build, crashed or hung
    result.error = e.what();
    result.students_error = true;
    result.students_failure = e.status() == "crashed"     ? CheckStatus::Crashed
                              : e.status() == "timed_out" ? CheckStatus::TimedOut
                                                          : CheckStatus::CompileError;
  } catch (const BuildError& e) {
    result.error = e.what();
    if (result.error.empty()) result.error = "the shaders did not build, and the driver's log is empty";
    // The student's fault when the same programs build with the solution's files in their place.
    try {
      result.students_error = renderer.set_features(lab.hooks(Impl::Solution)) && !lab.files(Impl::Exercise).empty();
    } catch (const std::exception&) {
      result.students_error = false;
    }
  } catch (const std::exception& e) {
    result.error = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// The box a scene is drawn in with these parameters: its own, with the ground plane the renderer adds.
Bounds drawn_bounds(const Scene& scene, const ParamSet& params) {
  return with_ground(scene, adds_ground(scene, params)).bounds();
}

std::string vector_text(const glm::dvec3& v) {
  char s[128];
  std::snprintf(s, sizeof s, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
  return s;
}

}  // namespace

CheckResult run_lab_check(Renderer& renderer, const Lab& lab, const Scene& scene, const CheckRun& run) {
  if (!run.foreign_scene) return grade_on(renderer, lab, scene, run);
  const auto start = std::chrono::steady_clock::now();
  ParamSet params = lab_params(lab);
  LabFrame frame;
  bool ground = false;
  try {
    for (const auto& a : run.assignments) params.apply_assignment(a);
    ground = adds_ground(scene, params);
    // The lab's own scene: the built-in one every lab is graded on without --scene (its conditions name the
    // others they use, e.g. "stacked", and those stay as they are).
    frame = lab_frame(drawn_bounds(scene, params), drawn_bounds(make_default_scene(), params));
  } catch (const std::exception&) {
    // A bad assignment: grade_on reports it as the lab's run does.
  }
  const Scene fitted = in_lab_frame(scene, frame);
  CheckResult result = grade_on(renderer, lab, fitted, run);
  if (result.error.empty()) {
    // The solution graded against itself needs no second run: its own result, the same frames and seed.
    if (run.impl == Impl::Solution && run.submission.empty()) {
      grade_against_solution(result, CheckResult(result));
    } else {
      CheckRun solution_run = run;
      solution_run.impl = Impl::Solution;
      solution_run.submission.clear();
      solution_run.out_dir.clear();
      grade_against_solution(result, grade_on(renderer, lab, fitted, solution_run));
    }
  }
  result.notes.push_back("graded in the lab's frame: this scene's box (centre " + vector_text(frame.from + scene.origin) +
                         (ground ? ", with the ground plane added to it" : "") + ") scaled by " + format("%.6g", frame.scale) +
                         " and centred where the lab's own scene is, so the lights, cameras and lengths the "
                         "lab's conditions give stand where they stand on the lab's scene");
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}


Bounds shadows_on_receiver(const Scene& scene, const glm::vec3& to_light) {
  Bounds b;
  for (const auto& mesh : scene.meshes) {
    if (mesh.name == "receiver") continue;
    const Bounds m = mesh.bounds();
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 c = m.corner(i);
      b.extend(glm::vec3(c.x, 0.0f, c.z));
      b.extend(c - to_light * (c.y / to_light.y));
    }
  }
  return b;
}

// The grazing light of grade_default_and_grazing (labs 13 and 14).
constexpr double kGrazingElevationDeg = 10.0;

void grade_default_and_grazing(CheckContext& ctx, CheckResult& result, const ParamSet& params, const Features& hooks,
                               const std::string& prefix) {
  ParamSet grazing = params;
  grazing.set("light.elevation", kGrazingElevationDeg);
  const std::pair<std::string, const ParamSet*> cases[] = {{"default", &params}, {"grazing", &grazing}};
  for (const auto& [tag, p] : cases)
    grade_hard_shadow(result, tag, ctx.measure(*p, hooks, prefix + "_" + tag + "_" + impl_name(ctx.impl)).metrics);
}

}  // namespace shadowlab
