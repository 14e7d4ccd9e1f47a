#include "renderer/depth_map_pass.h"

#include <stdexcept>

#include "renderer/billboards.h"
#include "renderer/shadow_target.h"

namespace shadowlab {

namespace {

GLenum depth_internal_format(const std::string& name) {
  if (name == "16") return GL_DEPTH_COMPONENT16;
  if (name == "32F") return GL_DEPTH_COMPONENT32F;
  return GL_DEPTH_COMPONENT24;
}

}  // namespace

DepthMapPass::DepthMapPass(const char* pass_name)
    : depth_({"shaders/shadow_depth.vert", {}, "shaders/shadow_depth.frag", {}, {}}),
      quad_({"shaders/fullscreen.vert", {}, "shaders/debug_depth.frag", {}, {}}),
      mask_(depth_.desc()),
      pass_name_(pass_name) {}

std::map<std::string, std::string> DepthMapPass::default_includes(LightType light) {
  // A perspective map's depth is not linear in distance: the spot's test compares distances.
  return {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
          {"lab/visibility.glsl", light == LightType::Spot ? "shaders/shadow/spot.glsl" : "shaders/shadow/hard.glsl"}};
}

bool DepthMapPass::set_includes(const IncludeMap&, const IncludeRules&) {
  // Its programs include no feature files; built here so that errors show when a feature is switched on.
  const bool depth_ok = depth_.rebuild();
  const bool mask_ok = mask_.follow(depth_.desc());
  return quad_.rebuild() && depth_ok && mask_ok;
}

void DepthMapPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(depth_);
  f(quad_);
  mask_.for_each_program(f);
}

void DepthMapPass::set_host_code(const GlHostCode& code) {
  if (code.create_shadow_target == code_.create_shadow_target && code.begin_shadow_pass == code_.begin_shadow_pass) return;
  code_ = code;
  size_ = 0;  // made again, by the new code, before the next map
}

bool DepthMapPass::ensure_targets(const ParamSet& params) {
  const int size = std::stoi(params.get(param::shadow_map_size));
  const std::string& format = params.get(param::shadow_depth_format);
  if (size == size_ && format == format_) return false;
  // The course's depth framebuffer, made by lab 0's GL solution (renderer/shadow_target.h) or, in the
  // window, by the student's own file.
  const ShadowTarget target = code_.create_shadow_target(size, depth_internal_format(format));
  // Adopted only when they are what they say (a student's may hand back 0 or a name it never made).
  depth_texture_ = glIsTexture(target.depth_texture) ? GlTexture::adopt(target.depth_texture) : GlTexture();
  fbo_ = glIsFramebuffer(target.framebuffer) ? GlFramebuffer::adopt(target.framebuffer) : GlFramebuffer();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  if (code_.own_shadow_target()) check_framebuffer("shadow map");
  else say_incomplete_target("shadow map", "create_shadow_target");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  size_ = size;
  format_ = format;
  return true;
}

void DepthMapPass::draw_map(PassContext& ctx) {
  ctx.timed(pass_name_, [&] {
    ctx.count_texels([&] {
      draw_depth(ctx);
      if (ctx.billboards) ctx.billboards->draw_shadow(ctx, ctx.light.view.view_projection());
    });
  });
}

void DepthMapPass::draw_depth(PassContext& ctx) {
  if (depth_u_.generation != depth_.generation())
    depth_u_ = {depth_.generation(), Uniform(depth_.id(), "u_light_view_proj")};
  code_.begin_shadow_pass({fbo_.id(), depth_texture_.id(), size_});
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(depth_.id());
  const glm::mat4 light_view_proj = ctx.light.view.view_projection();
  depth_u_.light_view_proj.set(light_view_proj);
  // Alpha-tested casters after the others, through the program that discards where the view does.
  draw_casters_from_light(ctx, light_view_proj, mask_.prepare(ctx.gpu_scene, [&](AlphaMaskVariant& v) {
    v.set("u_light_view_proj", light_view_proj);
  }));
}

LitBind DepthMapPass::lit_bind(GLuint program) const {
  return [this, compare = Uniform(program, "u_shadow_map_compare")](const ParamSet&) {
    if (compare.present()) {
      // PCF in hardware: the same depth texture on unit 1 through a sampler that compares (and filters
      // the four comparisons bilinearly); unit 0 keeps reading raw depths.
      if (!compare_sampler_) compare_sampler_ = make_compare_sampler();
      glActiveTexture(GL_TEXTURE1);
      glBindTexture(GL_TEXTURE_2D, depth_texture_.id());
      glBindSampler(1, compare_sampler_.id());
      compare.set(1);
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, depth_texture_.id());
  };
}

void DepthMapPass::draw_debug_quads(const DebugQuadArea& area) {
  if (quad_u_.generation != quad_.generation())
    quad_u_ = {quad_.generation(), Uniform(quad_.id(), "u_depth_map"), Uniform(quad_.id(), "u_rect")};
  area.place(area.width - area.side - 8, 8, area.side, area.side, "shadow map depth (light's view)");
  glUseProgram(quad_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, depth_texture_.id());
  quad_u_.depth_map.set(0);
  quad_u_.rect.set(glm::vec4(0, 0, 1, 1));
  glBindVertexArray(area.empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

std::vector<float> DepthMapPass::read_depth(int* size) const {
  *size = size_;
  return read_pixels(fbo_.id(), GL_NONE, size_, size_, GL_DEPTH_COMPONENT, 1);
}

std::vector<std::uint8_t> DepthMapPass::image(int* size) const {
  const std::vector<float> depth = read_depth(size);  // sets *size
  return depth_map_image(depth, *size);
}

}  // namespace shadowlab
