#include "renderer/msm_pass.h"

#include "core/vsm_params.h"

namespace shadowlab {

MsmPass::MsmPass()
    : moments_({"shaders/shadow_depth.vert", {}, "shaders/msm/moments.frag", {}, {}}), mask_(moments_.desc()) {}

std::map<std::string, std::string> MsmPass::default_includes(LightType) {
  return {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
          {"lab/visibility.glsl", "shaders/msm/visibility.glsl"},
          {"lab/msm_moments.glsl", "shaders/msm/power_moments.glsl"},
          {"lab/hamburger.glsl", "shaders/msm/hamburger.glsl"}};
}

bool MsmPass::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  ProgramDesc d = moments_.desc();
  d.includes = includes;
  d.rules = rules;
  moments_.set_desc(std::move(d));
  const bool ok = moments_.rebuild();
  return mask_.follow(moments_.desc()) && ok;
}

void MsmPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(moments_);
  mask_.for_each_program(f);
}

bool MsmPass::ensure_targets(const ParamSet& params) {
  const int size = std::stoi(params.get(param::shadow_map_size));
  if (size == size_) return false;
  // Linear filtering: the average of four texels' moments is again a set of moments.
  texture_ = make_texture_2d(GL_RGBA32F, size, size, GL_RGBA, GL_FLOAT, GL_LINEAR);
  depth_ = GlRenderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  check_framebuffer("moment shadow map");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  size_ = size;
  return true;
}

void MsmPass::draw_map(PassContext& ctx) {
  ctx.timed("moments", [&] {
    ctx.count_texels([&] {
      if (moments_u_.generation != moments_.generation())
        moments_u_ = {moments_.generation(), Uniform(moments_.id(), "u_light_view_proj")};
      bind_color_target(fbo_.id(), size_, size_);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glDepthMask(GL_TRUE);
      glClearBufferfv(GL_COLOR, 0, kMsmClear);
      glClearDepth(1.0);
      glClear(GL_DEPTH_BUFFER_BIT);
      glUseProgram(moments_.id());
      const glm::mat4 light_view_proj = ctx.light.view.view_projection();
      moments_u_.light_view_proj.set(light_view_proj);
      draw_casters_from_light(ctx, light_view_proj, mask_.prepare(ctx.gpu_scene, [&](AlphaMaskVariant& v) {
        v.set("u_light_view_proj", light_view_proj);
      }));
    });
  });
  ++ctx.stats.moments_passes;
}

LitBind MsmPass::lit_bind(GLuint program) const {
  return [this, moment_bias = Uniform(program, "u_msm_moment_bias")](const ParamSet& params) {
    moment_bias.set(params.get(param::vsm_msm_moment_bias));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.id());
  };
}

std::vector<float> MsmPass::read_depth(int* size) const {
  *size = size_;
  return read_pixels(fbo_.id(), GL_NONE, size_, size_, GL_DEPTH_COMPONENT, 1);
}

std::vector<std::uint8_t> MsmPass::image(int* size) const {
  const std::vector<float> depth = read_depth(size);  // sets *size
  return depth_map_image(depth, *size);
}

std::vector<float> MsmPass::read_moments() const {
  return read_pixels(fbo_.id(), GL_COLOR_ATTACHMENT0, size_, size_, GL_RGBA, 4);
}

}  // namespace shadowlab
