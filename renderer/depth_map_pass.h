// The plain shadow map of a directional or spot light (the course's first pass): the scene's depth seen
// from the light, in a depth texture with no colour buffer, compared in the lit pass with one tap or
// filtered (PCF, in the shader or through a comparison sampler: the shadow tests, renderer/shadow_test.h). A spot's map is a perspective
// projection: its default shadow test (shaders/shadow/spot.glsl) compares linear distances.
//
//   depth pass:  scene from the light -> depth texture (16, 24 or 32F bits, nearest)
#pragma once

#include <map>
#include <string>

#include "renderer/shadow_pass.h"

namespace shadowlab {

class DepthMapPass final : public ShadowPass {
 public:
  // `pass_name`: the pass's name in the frame's timings (a string literal).
  explicit DepthMapPass(const char* pass_name = "shadow");
  static std::map<std::string, std::string> default_includes(LightType light);

  bool set_includes(const IncludeMap& includes, const IncludeRules& rules) override;
  void for_each_program(const std::function<void(ReloadableProgram&)>& f) override;
  bool ensure_targets(const ParamSet& params) override;
  void set_host_code(const GlHostCode& code) override;
  void draw_map(PassContext& ctx) override;
  LitBind lit_bind(GLuint program) const override;
  void draw_debug_quads(const DebugQuadArea& area) override;
  int size() const override { return size_; }
  GLuint texture() const { return depth_texture_.id(); }
  std::vector<float> read_depth(int* size) const override;
  std::vector<std::uint8_t> image(int* size) const override;

 private:
  void draw_depth(PassContext& ctx);

  ReloadableProgram depth_, quad_;
  AlphaMaskVariant mask_;  // depth_ with ALPHA_MASK: alpha-tested (MASK) casters
  struct DepthUniforms {
    int generation = -1;
    Uniform light_view_proj;
  } depth_u_;
  struct QuadUniforms {
    int generation = -1;
    Uniform depth_map, rect;
  } quad_u_;
  const char* pass_name_;
  int size_ = 0;
  std::string format_;
  GlHostCode code_;  // who makes and begins the target (the renderer, or a student's loaded file)
  GlTexture depth_texture_;
  GlFramebuffer fbo_;
  // GL_COMPARE_REF_TO_TEXTURE with linear filtering, made when a shadow test reads a sampler2DShadow.
  mutable GlSampler compare_sampler_;
};

}  // namespace shadowlab
