// Moment shadow maps (Peters & Klein 2015, "Moment Shadow Mapping"), the four-moment Hamburger bound:
// the moments pass stores (z, z^2, z^3, z^4) of the nearest surface per texel in an RGBA32F texture
// (linear filtering; no blur: VSM's blurs are two-channel), and the lit pass bounds the shadow at depth z
// from below (the light from above) by the Hamburger problem's extreme distribution, the one with the
// least weight strictly in front of z (lab 14's msm_hamburger; solution shaders/msm/hamburger.glsl).
//
//   moments pass:  scene from the light -> moments texture (RGBA32F, linear) + D24 renderbuffer
//
// The texture is cleared to the far plane's moments (1, 1, 1, 1). The moment bias (vsm.msm_moment_bias)
// mixes (0.5, 0.5, 0.5, 0.5) into the filtered moments, the moments of half the weight at depth 0 and half
// at depth 1 (not a uniform distribution's), so the Hankel matrix stays positive definite in float32.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "renderer/shadow_pass.h"

namespace shadowlab {

inline constexpr float kMsmClear[4] = {1.0f, 1.0f, 1.0f, 1.0f};

class MsmPass final : public ShadowPass {
 public:
  MsmPass();
  static std::map<std::string, std::string> default_includes(LightType light);

  // Points the moments program's "lab/msm_moments.glsl" at its file and rebuilds it.
  bool set_includes(const IncludeMap& includes, const IncludeRules& rules) override;
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) override;
  // shadow.map_size: the RGBA32F texture and its depth renderbuffer.
  bool ensure_targets(const ParamSet& params) override;
  void draw_map(PassContext& ctx) override;
  // The moments on unit 0 and vsm.msm_moment_bias.
  LitBind lit_bind(GLuint program) const override;
  int size() const override { return size_; }
  std::vector<float> read_depth(int* size) const override;
  std::vector<std::uint8_t> image(int* size) const override;
  // The moments as RGBA quadruples, bottom row first.
  std::vector<float> read_moments() const;

 private:
  ReloadableProgram moments_;
  AlphaMaskVariant mask_;  // moments_ with ALPHA_MASK: alpha-tested (MASK) casters
  struct {
    int generation = -1;
    Uniform light_view_proj;
  } moments_u_;
  int size_ = 0;
  GlTexture texture_;
  GlRenderbuffer depth_;
  GlFramebuffer fbo_;
};

}  // namespace shadowlab
