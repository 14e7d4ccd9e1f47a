// The entries of PCSS for positional lights with a size (pcss_spot.cpp, pcss_point.cpp; their shaders
// share shaders/shadow/pcss_positional.glsl): the same uniforms, read from the light's size (a radius,
// world units) and the taps per side of the sun's PCSS parameters (pcss.cpp).
#pragma once

#include "core/technique_params.h"
#include "renderer/shader.h"
#include "renderer/shadow_test.h"

namespace shadowlab {

inline ShadowTest positional_pcss_test(const char* name, const char* file) {
  ShadowTest test{name, file, technique_param_specs({"pcss.blocker_samples", "pcss.filter_samples"}), {}, {}};
  test.resolve = [](GLuint id) -> ShadowTestBind {
    struct Uniforms {
      Uniform light_size, blocker_samples, filter_samples;
    };
    const Uniforms u{{id, "u_light_size"}, {id, "u_pcss_blocker_samples"}, {id, "u_pcss_filter_samples"}};
    return [u](const ShadowTestFrame& f) {
      u.light_size.set(f.light.size);
      u.blocker_samples.set(f.params.get(param::pcss_blocker_samples));
      u.filter_samples.set(f.params.get(param::pcss_filter_samples));
    };
  };
  return test;
}

}  // namespace shadowlab
