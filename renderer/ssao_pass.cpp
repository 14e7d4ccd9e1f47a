#include "renderer/ssao_pass.h"

#include <algorithm>
#include <random>
#include <stdexcept>

#include "core/ao_params.h"

namespace shadowlab {

namespace {
// Fixed seeds: the same kernel and noise in every run (a check's image does not change from run to run).
constexpr unsigned kKernelSeed = 17;
constexpr unsigned kNoiseSeed = 71;
constexpr GLenum kGbufferAttachments[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
}  // namespace

std::array<glm::vec3, kSsaoKernelSize> ssao_kernel() {
  std::mt19937 rng(kKernelSeed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::array<glm::vec3, kSsaoKernelSize> kernel{};
  for (int i = 0; i < kSsaoKernelSize; ++i) {
    // A point inside the unit hemisphere (z >= 0): drawn in the half cube, kept when inside the ball.
    glm::vec3 s;
    do {
      s = {unit(rng) * 2.0f - 1.0f, unit(rng) * 2.0f - 1.0f, unit(rng)};
    } while (glm::dot(s, s) > 1.0f || glm::dot(s, s) < 1e-6f);
    kernel[static_cast<std::size_t>(i)] = s;  // ssao.frag's ssao_kernel(i) scales it toward the centre
  }
  return kernel;
}

std::array<glm::vec3, kSsaoNoiseSide * kSsaoNoiseSide> ssao_noise() {
  std::mt19937 rng(kNoiseSeed);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::array<glm::vec3, kSsaoNoiseSide * kSsaoNoiseSide> noise{};
  for (auto& v : noise) v = {unit(rng), unit(rng), 0.0f};
  return noise;
}

SsaoPass::SsaoPass()
    : gbuffer_({"shaders/ssao/view_gbuffer.vert", {}, "shaders/ssao/view_gbuffer.frag", {}, {}}),
      ssao_({"shaders/fullscreen.vert", {}, "shaders/ssao/ssao.frag", {}, {}}),
      gtao_({"shaders/fullscreen.vert", {}, "shaders/ssao/gtao.frag", {}, {}}),
      blur_({"shaders/fullscreen.vert", {}, "shaders/ssao/blur.frag", {}, {}}),
      composite_({"shaders/fullscreen.vert", {}, "shaders/ssao/composite.frag", {}, {}}),
      quad_({"shaders/fullscreen.vert", {}, "shaders/ssao/quad.frag", {}, {}}),
      kernel_(ssao_kernel()) {
  if (!gbuffer_.rebuild() || !blur_.rebuild() || !composite_.rebuild() || !quad_.rebuild())
    throw std::runtime_error("cannot build the SSAO pass's shaders:\n" + gbuffer_.error() + blur_.error() +
                             composite_.error() + quad_.error());
  const auto noise = ssao_noise();
  noise_ = make_texture_2d(GL_RGB32F, kSsaoNoiseSide, kSsaoNoiseSide, GL_RGB, GL_FLOAT, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, noise_.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSsaoNoiseSide, kSsaoNoiseSide, GL_RGB, GL_FLOAT, noise.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);  // tiled over the screen
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
}

bool SsaoPass::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  ProgramDesc desc = ssao_.desc();
  desc.includes = includes;
  desc.includes.emplace("lab/ssao.glsl", "shaders/ssao/ssao_core.glsl");  // unless a lab gives one
  desc.rules = rules;
  ssao_.set_desc(desc);
  ProgramDesc gtao = gtao_.desc();
  gtao.includes = includes;
  gtao.includes.emplace("ao/gtao.glsl", "shaders/ssao/gtao_core.glsl");  // unless a test gives one
  gtao.rules = rules;
  gtao_.set_desc(gtao);
  const bool ssao_ok = ssao_.rebuild();
  return gtao_.rebuild() && ssao_ok;
}

void SsaoPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(gbuffer_);
  f(ssao_);
  f(gtao_);
  f(blur_);
  f(composite_);
  f(quad_);
}

void SsaoPass::ensure_targets(int width, int height) {
  if (width == width_ && height == height_ && gbuffer_fbo_) return;
  width_ = width;
  height_ = height;
  position_ = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
  normal_ = make_texture_2d(GL_RGBA16F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
  open_ = make_texture_2d(GL_R32F, width, height, GL_RED, GL_FLOAT, GL_NEAREST);
  blurred_open_ = make_texture_2d(GL_R32F, width, height, GL_RED, GL_FLOAT, GL_NEAREST);
  depth_ = GlRenderbuffer::create();
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  gbuffer_fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, position_.id(), 0);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, normal_.id(), 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.id());
  glDrawBuffers(2, kGbufferAttachments);
  check_framebuffer("SSAO G-buffer");
  open_fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, open_fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, open_.id(), 0);
  check_framebuffer("SSAO");
  blurred_fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, blurred_fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, blurred_open_.id(), 0);
  check_framebuffer("SSAO blur");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {

void bind_sampler(int unit, GLuint texture, const Uniform& sampler) {
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  glBindTexture(GL_TEXTURE_2D, texture);
  sampler.set(unit);
}

}  // namespace

void SsaoPass::draw_gbuffer(PassContext& ctx) {
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glDrawBuffers(2, kGbufferAttachments);
  glViewport(0, 0, width_, height_);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glUseProgram(gbuffer_.id());
  const GbufferUniforms& u = gbuffer_u_.get(gbuffer_, [](GLuint id) {
    return GbufferUniforms{{id, "u_view"}, {id, "u_projection"}};
  });
  u.view.set(ctx.camera_view);
  u.projection.set(ctx.camera_projection);
  ctx.gpu_scene.bind();
  for (const auto& range : ctx.gpu_scene.ranges()) {
    ctx.gpu_scene.draw(range);
    ++ctx.stats.draws;
  }
}

void SsaoPass::draw_ssao(PassContext& ctx) {
  const ParamSet& params = ctx.params;
  glBindFramebuffer(GL_FRAMEBUFFER, open_fbo_.id());
  glViewport(0, 0, width_, height_);
  glUseProgram(ssao_.id());
  const SsaoUniforms& u = ssao_u_.get(ssao_, [](GLuint id) {
    return SsaoUniforms{{id, "u_position"}, {id, "u_normal"},      {id, "u_noise"},     {id, "u_noise_scale"},
                        {id, "u_use_noise"}, {id, "u_projection"}, {id, "u_view"},      {id, "u_kernel"},
                        {id, "u_samples"},  {id, "u_radius"},      {id, "u_bias"},      {id, "u_range_check"}};
  });
  bind_sampler(0, position_.id(), u.position);
  bind_sampler(1, normal_.id(), u.normal);
  bind_sampler(2, noise_.id(), u.noise);
  u.noise_scale.set(glm::vec2(static_cast<float>(width_), static_cast<float>(height_)) / static_cast<float>(kSsaoNoiseSide));
  u.use_noise.set(params.get(param::ssao_noise) ? 1 : 0);
  u.projection.set(ctx.camera_projection);
  u.view.set(ctx.camera_view);
  u.kernel.set(kernel_.data(), kSsaoKernelSize);
  u.samples.set(std::clamp(params.get(param::ssao_samples), 1, kSsaoKernelSize));
  u.radius.set(params.get(param::ssao_radius));
  u.bias.set(params.get(param::ssao_bias));
  u.range_check.set(params.get(param::ssao_range_check) ? 1 : 0);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void SsaoPass::draw_blur(PassContext&) {
  glBindFramebuffer(GL_FRAMEBUFFER, blurred_fbo_.id());
  glViewport(0, 0, width_, height_);
  glUseProgram(blur_.id());
  const BlurUniforms& u = blur_u_.get(blur_, [](GLuint id) { return BlurUniforms{{id, "u_open"}, {id, "u_position"}}; });
  bind_sampler(0, open_.id(), u.open);
  bind_sampler(1, position_.id(), u.position);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void SsaoPass::draw(PassContext& ctx, const ViewTarget& view) {
  const ParamSet& params = ctx.params;
  ensure_targets(view.width, view.height);
  // 1. View-space positions and normals.
  ctx.timed("ssao_gbuffer", [&] { draw_gbuffer(ctx); });
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(ctx.empty_vao);
  // 2. The AO buffer: SSAO's, or GTAO's (ssao_gtao.cpp).
  const bool gtao = params.get(param::ssao_method) == "gtao";
  if (gtao) ctx.timed("gtao", [&] { draw_gtao(ctx); });
  if (!gtao) ctx.timed("ssao", [&] { draw_ssao(ctx); });
  // 3. The blur over the noise's tile.
  blurred_ = params.get(param::ssao_blur);
  if (blurred_) ctx.timed("ssao_blur", [&] { draw_blur(ctx); });
  const GLuint shown = blurred_ ? blurred_open_.id() : open_.id();
  // 4. The lit picture times the AO.
  ctx.timed("ssao_composite", [&] {
    bind_color_target(view.framebuffer, view.width, view.height);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);
    glUseProgram(composite_.id());
    const ImageUniforms& u = composite_u_.get(composite_, [](GLuint id) { return ImageUniforms{{id, "u_open"}, {}}; });
    bind_sampler(0, shown, u.image);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
  });
  if (params.get(param::view_debug_quad)) ctx.timed("ssao_quads", [&] { debug_quads(ctx, view); });
  glActiveTexture(GL_TEXTURE0);
  glEnable(GL_DEPTH_TEST);
  glViewport(0, 0, view.width, view.height);
}

void SsaoPass::debug_quads(PassContext& ctx, const ViewTarget& view) {
  bind_color_target(view.framebuffer, view.width, view.height);
  const int side =
      std::max(8, static_cast<int>(static_cast<float>(view.height) * ctx.params.get(param::view_debug_quad_size)));
  const int quad_width = std::max(8, side * view.width / std::max(1, view.height));
  glUseProgram(quad_.id());
  const ImageUniforms& u = quad_u_.get(quad_, [](GLuint id) { return ImageUniforms{{id, "u_image"}, {id, "u_is_noise"}}; });
  u.image.set(0);
  glActiveTexture(GL_TEXTURE0);
  std::vector<DebugQuadLabel>* labels = ctx.annotations ? &ctx.annotations->quads : nullptr;
  // Along the bottom left, clear of the shadow map's quad on the right.
  struct Quad {
    GLuint texture;
    bool noise;
    int width;
    const char* label;
  };
  const Quad quads[3] = {{open_.id(), false, quad_width, "AO buffer"},
                         {noise_.id(), true, side, "noise 4 x 4"},
                         {blurred_ ? blurred_open_.id() : open_.id(), false, quad_width, blurred_ ? "AO blurred" : "AO (blur off)"}};
  int x = 8;
  for (const Quad& q : quads) {
    glViewport(x, 8, q.width, side);
    if (labels) labels->push_back({x, 8, q.width, side, q.label});
    glBindTexture(GL_TEXTURE_2D, q.texture);
    u.is_noise.set(q.noise ? 1 : 0);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++ctx.stats.draws;
    x += q.width + 8;
  }
}

std::vector<float> SsaoPass::read_open(bool blurred) const {
  if (!open_fbo_) return {};
  return read_pixels(blurred && blurred_ ? blurred_fbo_.id() : open_fbo_.id(), GL_COLOR_ATTACHMENT0, width_, height_, GL_RED, 1);
}

}  // namespace shadowlab
