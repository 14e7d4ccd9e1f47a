// Percentage-closer soft shadows (shaders/shadow/pcss.glsl, around lab 16's penumbra estimate): a
// blocker search, the penumbra's width from the light's size, PCF over that width. Reads the light's
// size, its taps per side and its debug view (pcss.view), whose legend it adds to the frame's words.
#include <utility>

#include "core/technique_params.h"
#include "renderer/debug_annotations.h"
#include "renderer/shader.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

namespace {

struct PcssUniforms {
  Uniform light_size, blocker_samples, filter_samples, view, view_range;
};

}  // namespace

ShadowTest SHADOWLAB_SHADOW_TEST_MAKER() {
  ShadowTest test{"pcss", "shaders/shadow/pcss.glsl",
                  technique_param_specs({"pcss.blocker_samples", "pcss.filter_samples", "pcss.view", "pcss.view_range"}),
                  {}, {}};
  test.resolve = [](GLuint id) -> ShadowTestBind {
    const PcssUniforms u{{id, "u_light_size"}, {id, "u_pcss_blocker_samples"}, {id, "u_pcss_filter_samples"},
                         {id, "u_pcss_view"}, {id, "u_pcss_view_range"}};
    return [u](const ShadowTestFrame& f) {
      // A sized light as given (light.size: a directional light's angular diameter in degrees, a
      // positional light's radius), and the samples per side (blocker search, filter).
      u.light_size.set(f.light.size);
      u.blocker_samples.set(f.params.get(param::pcss_blocker_samples));
      u.filter_samples.set(f.params.get(param::pcss_filter_samples));
      u.view.set(f.params.index(param::pcss_view));
      u.view_range.set(pcss_view_range(f.params));  // the legend's high end too (debug_annotations.h)
      // A program with the debug view (it reads u_pcss_view) shows a colour ramp: its legend, once.
      if (f.annotations && u.view.present() && f.annotations->legends.empty())
        if (auto legend = pcss_view_legend(f.params)) f.annotations->legends.push_back(std::move(*legend));
    };
  };
  return test;
}

}  // namespace shadowlab
