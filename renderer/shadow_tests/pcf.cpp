// Percentage-closer filtering (shaders/shadow/pcf.glsl, lab 6's solution): the comparison averaged over
// N x N texels, each tap in the shader or through the map's comparison sampler (u_shadow_map_compare,
// bound by the depth map's pass). Its kernel and comparison are compiled in as constants.
#include <string>

#include "core/technique_params.h"
#include "renderer/shader.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace {

// The kernel's radius ((N - 1) / 2): pcf.kernel's, or the one matched to the light (pcf.match_light,
// `matched` >= 0); and whether each tap compares in hardware.
int pcf_radius(const ParamSet& params, int matched) {
  if (matched >= 0 && params.get(param::pcf_match_light)) return matched;
  return std::stoi(params.get(param::pcf_kernel)) / 2;
}
bool pcf_hardware(const ParamSet& params) { return params.get(param::pcf_hardware); }

}  // namespace

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() {
  ShadowTest test{"pcf", "shaders/shadow/pcf.glsl",
                  technique_param_specs({"pcf.kernel", "pcf.hardware", "pcf.match_light", "pcf.match_distance"}), {}, {}};
  test.resolve = [](GLuint program) -> ShadowTestBind {
    return [radius = Uniform(program, "u_pcf_radius"), hardware = Uniform(program, "u_pcf_hardware")](const ShadowTestFrame& f) {
      radius.set(pcf_radius(f.params, f.matched_radius));
      hardware.set(pcf_hardware(f.params) ? 1 : 0);
    };
  };
  // The kernel bounds its loops and the hardware flag picks each tap's comparison: compiled in, a 3 x 3
  // kernel is nine unrolled taps of one kind, as a hand-written shader for it would be.
  test.constants = [](const ShadowTestFrame& f, LitConstants& out) {
    const std::size_t at = out.size();
    out.resize(at + 2);
    out[at].first = "u_pcf_radius";
    out[at].second = std::to_string(pcf_radius(f.params, f.matched_radius));
    out[at + 1].first = "u_pcf_hardware";
    out[at + 1].second = pcf_hardware(f.params) ? "1" : "0";
  };
  return test;
}

}  // namespace shadowlab
