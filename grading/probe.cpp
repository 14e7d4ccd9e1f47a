#include "grading/probe.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "grading/check.h"
#include "grading/lab.h"
#include "renderer/gl_objects.h"
#include "renderer/shader.h"

namespace shadowlab {

namespace {

constexpr int kRowWidth = 256;  // cases per row of the probe's textures
constexpr int kInputUnit0 = 6, kInputUnit1 = 7;

GlTexture input_texture(const std::vector<glm::vec4>& values, int width, int height) {
  std::vector<glm::vec4> padded(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), glm::vec4(0.0f));
  std::copy(values.begin(), values.end(), padded.begin());
  GlTexture t = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, padded.data());
  return t;
}

}  // namespace

GlTexture make_probe_depth_texture(const std::vector<float>& depths, int size) {
  if (depths.size() != static_cast<std::size_t>(size) * static_cast<std::size_t>(size))
    throw std::invalid_argument("probe: depth texture of the wrong size");
  GlTexture t = make_texture_2d(GL_DEPTH_COMPONENT32F, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

GlTexture make_probe_moments_texture(const std::vector<glm::vec2>& moments, int width, int height) {
  std::vector<glm::vec2> padded(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), glm::vec2(1.0f));
  if (moments.size() > padded.size()) throw std::invalid_argument("probe: more moments than texels");
  std::copy(moments.begin(), moments.end(), padded.begin());
  GlTexture t = make_texture_2d(GL_RG32F, width, height, GL_RG, GL_FLOAT, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RG, GL_FLOAT, padded.data());
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

void bind_probe_shadow_map(GLuint program, const GlTexture& depth, const GlSampler& compare) {
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, depth.id());
  set_uniform(program, "u_shadow_map", 0);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, depth.id());
  glBindSampler(1, compare.id());
  set_uniform(program, "u_shadow_map_compare", 1);
  glActiveTexture(GL_TEXTURE0);
}

std::vector<BiasThreshold> sweep_bias(const Features& hooks, const BiasSweep& sweep) {
  constexpr int kSteps = 600;
  const std::vector<double>& kNdotL = sweep.n_dot_l;
  std::vector<double> offsets;
  for (int j = 0; j < kSteps; ++j) offsets.push_back(sweep.distance * std::pow(10.0, -5.0 + 5.0 * j / (kSteps - 1)));
  ProbeRequest request;
  request.fragment = "shaders/probe/visibility.frag";
  for (double c : kNdotL) {
    // A normal at the wanted angle to the light: tilted from the direction toward the light.
    const glm::vec3 to_light = -sweep.direction;
    glm::vec3 side = glm::cross(to_light, std::abs(to_light.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0));
    side = glm::normalize(side);
    const glm::vec3 n = static_cast<float>(c) * to_light + static_cast<float>(std::sqrt(1.0 - c * c)) * side;
    for (double x : offsets) {
      const glm::vec3 p = sweep.direction * static_cast<float>(sweep.distance + x);
      request.in0.push_back({p, static_cast<float>(c)});
      request.in1.push_back({n, 0.0f});
    }
  }
  for (float angle : sweep.texel_angles)
    request.passes.push_back([&sweep, angle](GLuint program) { sweep.setup(program, sweep.distance, angle); });
  const auto v = run_probe(hooks, request);
  std::vector<BiasThreshold> out;
  for (std::size_t pass = 0; pass < v.size(); ++pass)
    for (std::size_t k = 0; k < kNdotL.size(); ++k) {
      double bias = std::numeric_limits<double>::infinity();
      for (int j = 0; j < kSteps; ++j)
        if (!(v[pass][k * kSteps + static_cast<std::size_t>(j)] >= 0.5f)) {
          bias = j == 0 ? 0.0 : offsets[static_cast<std::size_t>(j)];
          break;
        }
      out.push_back({sweep.distance, kNdotL[k], sweep.texel_angles[pass], bias});
    }
  return out;
}

// The bias probe's limits, as ratios of the bias found to a texel's footprint with its slope term.
constexpr double kMinBiasRatio = 0.5;         // below: acne
constexpr double kMaxBiasRatio = 4.0;         // above: peter-panning
constexpr double kMaxBiasRatioSpread = 1.4;   // per n.l, largest over least ratio across distances and texel sizes
constexpr double kMinBiasSlopeGrowth = 1.5;   // bias(n.l = 0.5) / bias(n.l = 1), median
// The course's cap on tan(angle of incidence) (lab 1; shaders/shadow/slope.glsl:MAX_TAN_INCIDENCE): the
// footprint a grazing case is graded against stops growing there, as the solutions' bias does.
constexpr double kMaxTanIncidence = 10.0;

void grade_bias_thresholds(CheckResult& result, const std::vector<BiasThreshold>& thresholds, double slope) {
  double least = std::numeric_limits<double>::infinity(), most = 0.0;
  std::map<double, std::pair<double, double>> per_slope;  // n.l -> (least, most) ratio
  std::map<double, std::vector<double>> by_n_dot_l;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& t : thresholds) {
    const double tan_a = std::min(std::sqrt(1.0 - t.n_dot_l * t.n_dot_l) / t.n_dot_l, kMaxTanIncidence);
    const double footprint = t.distance * t.texel_angle * (1.0 + slope * tan_a);
    const double ratio = t.bias / footprint;
    least = std::min(least, ratio);
    most = std::max(most, std::isfinite(ratio) ? ratio : 1e30);
    auto& [lo, hi] = per_slope.try_emplace(t.n_dot_l, std::numeric_limits<double>::infinity(), 0.0).first->second;
    lo = std::min(lo, ratio);
    hi = std::max(hi, std::isfinite(ratio) ? ratio : 1e30);
    by_n_dot_l[t.n_dot_l].push_back(t.bias);
    list.push_back({{"distance", t.distance}, {"n_dot_l", t.n_dot_l}, {"texel_angle", t.texel_angle},
                    {"bias", std::isfinite(t.bias) ? t.bias : -1.0}, {"footprint_bias", footprint}});
  }
  double spread = 1.0;
  for (const auto& [c, range] : per_slope) spread = std::max(spread, range.first > 0 ? range.second / range.first : 1e30);
  // The bias's growth with the slope: median over the cases of bias(n.l = 0.5) / bias(n.l = 1).
  std::vector<double> growth;
  const auto& at_one = by_n_dot_l[1.0];
  const auto& at_half = by_n_dot_l[0.5];
  for (std::size_t i = 0; i < std::min(at_one.size(), at_half.size()); ++i)
    growth.push_back(at_one[i] > 0 ? at_half[i] / at_one[i] : 0.0);
  std::sort(growth.begin(), growth.end());
  const double slope_growth = growth.empty() ? 0.0 : growth[growth.size() / 2];
  result.metrics["bias_probe"] = list;
  const std::string why = "probe: the offset at which a point behind a stored occluder turns shadowed, against "
                          "distance x texel angle x (1 + slope x tan)";
  result.criteria.push_back({"bias.too_small", least, Criterion::kAtLeast, kMinBiasRatio, why,
                             "the bias must cover a texel's footprint at the fragment's distance (distance x "
                             "u_texel_angle), or surfaces shadow themselves (acne)."});
  result.criteria.push_back({"bias.too_large", most, Criterion::kAtMost, kMaxBiasRatio, why,
                             "the bias is several texels' footprints too large: shadows detach (peter-panning)."});
  result.criteria.push_back({"bias.not_proportional", spread, Criterion::kAtMost, kMaxBiasRatioSpread, why,
                             "the bias must grow in proportion to the distance from the light and to u_texel_angle "
                             "(a texel's footprint), not be a constant tuned to one place or map size."});
  result.criteria.push_back({"bias.slope_growth", slope_growth, Criterion::kAtLeast, kMinBiasSlopeGrowth, why,
                             "the bias must grow with the slope (u_bias_slope x tan of the angle of incidence)."});
}

void set_uniform(GLuint program, const char* name, float value) { glUniform1f(glGetUniformLocation(program, name), value); }
void set_uniform(GLuint program, const char* name, int value) { glUniform1i(glGetUniformLocation(program, name), value); }
void set_uniform(GLuint program, const char* name, const glm::mat4& value) {
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, &value[0][0]);
}
void set_uniform(GLuint program, const char* name, const glm::vec3& value) {
  glUniform3f(glGetUniformLocation(program, name), value.x, value.y, value.z);
}

std::vector<std::vector<float>> run_probe(const Features& hooks, const ProbeRequest& request) {
  const std::size_t cases = request.in0.size();
  const std::size_t passes = std::max<std::size_t>(request.passes.size(), 1);
  if (cases == 0) return std::vector<std::vector<float>>(passes);
  if (!request.in1.empty() && request.in1.size() != cases) throw std::invalid_argument("probe: in0 and in1 differ in size");
  ProgramDesc desc{"shaders/fullscreen.vert", {}, request.fragment, {}, {}, hooks.include_rules};
  if (hooks.own_shadow_coords) desc.defines.emplace_back(kOwnShadowCoordsDefine, "1");
  for (const auto& [name, file] : Renderer::default_includes(hooks.technique, hooks.light.value_or(LightType::Directional)))
    desc.includes[name] = file;
  for (const auto& [name, file] : hooks.includes) desc.includes[name] = file;
  ProgramBuild build = build_program(desc);
  if (!build.program) throw BuildError(build.error);

  const int width = static_cast<int>(std::min<std::size_t>(cases, kRowWidth));
  const int height = static_cast<int>((cases + kRowWidth - 1) / kRowWidth);
  GlTexture in0 = input_texture(request.in0, width, height);
  GlTexture in1 = input_texture(request.in1.empty() ? std::vector<glm::vec4>{} : request.in1, width, height);
  GlTexture out = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
  GlFramebuffer fbo = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out.id(), 0);
  check_framebuffer("probe");
  GlVertexArray vao = GlVertexArray::create();

  const GLuint program = build.program.id();
  glUseProgram(program);
  glActiveTexture(GL_TEXTURE0 + kInputUnit0);
  glBindTexture(GL_TEXTURE_2D, in0.id());
  set_uniform(program, "u_probe_in0", kInputUnit0);
  glActiveTexture(GL_TEXTURE0 + kInputUnit1);
  glBindTexture(GL_TEXTURE_2D, in1.id());
  set_uniform(program, "u_probe_in1", kInputUnit1);
  glActiveTexture(GL_TEXTURE0);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(vao.id());
  std::vector<std::vector<float>> values(passes, std::vector<float>(cases));
  std::vector<glm::vec4> result(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t pass = 0; pass < passes; ++pass) {
    if (pass < request.passes.size() && request.passes[pass]) request.passes[pass](program);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, result.data());
    for (std::size_t i = 0; i < cases; ++i) values[pass][i] = result[i].x;
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  for (int unit : {0, 1, 2, 3, kInputUnit0, kInputUnit1}) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindSampler(static_cast<GLuint>(unit), 0);
  }
  glActiveTexture(GL_TEXTURE0);
  return values;
}

ProbeTally probe_kinds(CheckResult& result, const Features& hooks, const char* fragment, const std::vector<ProbeCase>& cases,
                       const std::vector<ProbeKind>& kinds, double tolerance, double max_mismatch, const std::string& why) {
  ProbeRequest request;
  request.fragment = fragment;
  for (const ProbeCase& c : cases) {
    request.in0.push_back(c.in0);
    request.in1.push_back(c.in1);
  }
  const std::vector<float> got = run_probe(hooks, request)[0];
  ProbeTally tally;
  tally.cases.assign(kinds.size(), 0);
  std::vector<int> wrong(kinds.size(), 0);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto k = static_cast<std::size_t>(cases[i].kind);
    const double error = std::abs(static_cast<double>(got[i]) - cases[i].want);
    wrong[k] += !(error <= tolerance);  // NaN is off
    ++tally.cases[k];
    tally.worst_error = std::max(tally.worst_error, std::isfinite(error) ? error : 1e30);
  }
  for (std::size_t k = 0; k < kinds.size(); ++k)
    result.criteria.push_back({kinds[k].metric, tally.cases[k] ? static_cast<double>(wrong[k]) / tally.cases[k] : 1.0,
                               Criterion::kAtMost, max_mismatch, why, kinds[k].advice});
  return tally;
}

}  // namespace shadowlab
