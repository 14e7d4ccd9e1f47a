#include "labs/vsm_features.h"

namespace shadowlab {

Features vsm_features(const std::filesystem::path& visibility) {
  Features hooks;
  hooks.technique = ShadowTechnique::Moments;
  hooks.includes["lab/visibility.glsl"] = visibility.string();
  return hooks;
}

std::vector<ParamSpec> vsm_lab_bias_params() {
  ParamSpec bias = param::shadow_bias.spec(), slope = param::shadow_slope_bias.spec();
  bias.default_value = 0.0005;
  slope.default_value = 0.0;
  return {bias, slope};
}

}  // namespace shadowlab
