// Percentage-closer soft shadows for a point light with a size (shaders/shadow/pcss_point.glsl): the sun's
// three steps (renderer/shadow_tests/pcss.cpp) measured around the ray to the point on the six faces, on a Vogel spiral turned
// per pixel. Reads the light's size (a radius, world units) and the taps per side of pcss.cpp's parameters.
#include "core/technique_params.h"
#include "renderer/shader.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace {

struct PcssPointUniforms {
  Uniform light_size, blocker_samples, filter_samples;
};

}  // namespace

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() {
  ShadowTest test{"pcss_point", "shaders/shadow/pcss_point.glsl",
                  technique_param_specs({"pcss.blocker_samples", "pcss.filter_samples"}), {}, {}};
  test.resolve = [](GLuint id) -> ShadowTestBind {
    const PcssPointUniforms u{{id, "u_light_size"}, {id, "u_pcss_blocker_samples"}, {id, "u_pcss_filter_samples"}};
    return [u](const ShadowTestFrame& f) {
      u.light_size.set(f.light.size);
      u.blocker_samples.set(f.params.get(param::pcss_blocker_samples));
      u.filter_samples.set(f.params.get(param::pcss_filter_samples));
    };
  };
  return test;
}

}  // namespace shadowlab
