// Probes: a lab's GLSL function run on inputs the check chooses rather than on a scene, one fragment
// per case, with the lab's own includes and include rules. A check compares the results with a CPU
// reference of the same definition, so a function is graded everywhere in its domain, not only where
// one scene happens to exercise it (e.g. a kernel's shape on straight edges at every orientation,
// Chebyshev's bound at every mean, variance and depth).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl.h"
#include "renderer/renderer.h"

namespace shadowlab {

struct ProbeRequest {
  std::string fragment;            // e.g. "shaders/probe/visibility.frag"
  std::vector<glm::vec4> in0, in1;  // per case: the shader's u_probe_in0 and u_probe_in1 (in1 may be empty)
  // One pass over every case per entry, each setting the function's uniforms and textures on the bound
  // program (texture units 0-3 are the check's; the probe's inputs use units 6 and 7). Empty: one pass
  // with the uniforms at their defaults.
  std::vector<std::function<void(GLuint program)>> passes;
};

// Runs the probe with the hooks' includes (over the renderer's defaults for its technique and light)
// and returns, per pass, one value per case (the fragment's red channel). Throws BuildError when it
// does not build.
std::vector<std::vector<float>> run_probe(const Features& hooks, const ProbeRequest& request);

// A depth texture for probes: size x size texels, row 0 at v = 0 (GL's order), nearest filtering,
// clamped to the edge, no comparison (as the renderer's shadow map reads through u_shadow_map).
GlTexture make_probe_depth_texture(const std::vector<float>& depths, int size);
// A two-channel float texture for probes (a moments map: E[z], E[z^2] per texel), width x height texels,
// row 0 at v = 0, nearest filtering, clamped to the edge.
GlTexture make_probe_moments_texture(const std::vector<glm::vec2>& moments, int width, int height);

// Binds `depth` as u_shadow_map (unit 0) and, through a comparing, bilinear sampler, as
// u_shadow_map_compare (unit 1), as the lit pass does. The sampler must outlive the draw.
void bind_probe_shadow_map(GLuint program, const GlTexture& depth, const GlSampler& compare);
// (The sampler: make_compare_sampler(), renderer/gl_objects.h.)

// The bias a positional light's shadow test really applies, in world units, found by sweeping points away
// from a stored occluder: `setup` binds an occluder at `distance` from the light (a uniform map) and the
// uniforms of one texel angle; the points lie along `direction` from the light at distance + x, for x
// from 1e-5 to 1 times the distance (log-spaced), at each n . l of `n_dot_l`. Per (n . l, texel angle):
// the first x at which the point is shadowed (0 when shadowed at once, +inf when never).
struct BiasSweep {
  double distance = 5.0;
  glm::vec3 direction{0, 0, -1};  // unit, from the light
  std::vector<float> texel_angles;
  // The angles of incidence probed; 1 and 0.5 must be among them (bias.slope_growth compares the two).
  // A probe that stops at 0.5 (60 degrees) never sees a slope term that is wrong only at grazing light.
  std::vector<double> n_dot_l{1.0, 0.5};
  std::function<void(GLuint program, double distance, float texel_angle)> setup;
};
struct BiasThreshold {
  double distance, n_dot_l, texel_angle, bias;
};
std::vector<BiasThreshold> sweep_bias(const Features& hooks, const BiasSweep& sweep);

// Grades the thresholds against the footprint bias the lab teaches, distance x texel angle x
// (1 + slope x tan(angle of incidence)), tan capped at 10 as lab 1 teaches (shaders/shadow/slope.glsl; the
// cap matters only below n . l = 0.0995, 84.3 degrees): adds bias.too_small (least ratio, >= 0.5), bias.too_large
// (largest, <= 4), bias.not_proportional (per n . l, largest over least ratio, <= 1.4: it must scale with
// distance and texel size as a texel's footprint does) and bias.slope_growth (the bias at n . l = 0.5
// over the bias at 1, >= 1.5).
struct CheckResult;
void grade_bias_thresholds(CheckResult& result, const std::vector<BiasThreshold>& thresholds, double slope);

// Sets a uniform by name on the bound program; a uniform the student's code does not use is optimised
// away, which is fine (setting it is then a no-op).
void set_uniform(GLuint program, const char* name, float value);
void set_uniform(GLuint program, const char* name, int value);
void set_uniform(GLuint program, const char* name, const glm::mat4& value);
void set_uniform(GLuint program, const char* name, const glm::vec3& value);

// A probe whose cases fall into kinds (e.g. lit, one bound the smaller, the other): runs `fragment` on
// every case's inputs and adds, per kind, the criterion `metric` (at most `max_mismatch`: the share of that
// kind's cases whose result is off `want` by more than `tolerance`; NaN counts as off, a kind without cases
// as all off), with `why` and the kind's advice.
struct ProbeCase {
  glm::vec4 in0, in1;
  double want = 0.0;
  int kind = 0;
};
struct ProbeKind {
  const char* metric;
  const char* advice;
};
struct ProbeTally {
  std::vector<int> cases;  // per kind
  double worst_error = 0.0;
};
ProbeTally probe_kinds(CheckResult& result, const Features& hooks, const char* fragment, const std::vector<ProbeCase>& cases,
                       const std::vector<ProbeKind>& kinds, double tolerance, double max_mismatch, const std::string& why);

}  // namespace shadowlab
