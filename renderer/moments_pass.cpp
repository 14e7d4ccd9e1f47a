#include "renderer/moments_pass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "renderer/blur_passes.h"
#include "core/vsm_params.h"
#include "renderer/moments_target.h"

namespace shadowlab {

namespace {

// The moments' internal format: vsm.format, or its RGBA variant for four moments (EVSM).
GLenum moments_format(const std::string& format, bool four) {
  if (format == "RG16F") return four ? GL_RGBA16F : GL_RG16F;
  return four ? GL_RGBA32F : GL_RG32F;
}

ProgramDesc blur_desc(const char* direction) {
  return {"shaders/fullscreen.vert", {}, "shaders/vsm/blur.frag", {{"BLUR_DIRECTION", direction}}, {}};
}

bool has_compute_shaders() { return epoxy_gl_version() >= 43; }

}  // namespace

MomentsPass::MomentsPass()
    : moments_({"shaders/shadow_depth.vert", {}, "shaders/vsm/moments.frag", {}, {}}),
      blur_x_(blur_desc("ivec2(1, 0)")),
      blur_y_(blur_desc("ivec2(0, 1)")),
      debug_({"shaders/fullscreen.vert", {}, "shaders/vsm/debug_moments.frag", {}, {}}),
      mask_(moments_.desc()),
      fast_path_(has_compute_shaders() ? FastPath::Compute : FastPath::Fragment) {}

std::map<std::string, std::string> MomentsPass::default_includes(LightType) {
  return {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
          {"lab/visibility.glsl", "shaders/vsm/visibility.glsl"},
          {"lab/moments.glsl", "shaders/vsm/moments.glsl"},
          {"lab/chebyshev.glsl", "shaders/vsm/chebyshev.glsl"},
          {"lab/blur.glsl", "shaders/vsm/gaussian_blur.glsl"}};
}

void MomentsPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(moments_);
  mask_.for_each_program(f);
  f(blur_x_);
  f(blur_y_);
  f(debug_);
  for (auto& [radius, fast] : fast_fragment_) {
    f(fast.x);
    f(fast.y);
  }
  if (brute_.valid()) f(brute_);
}

bool MomentsPass::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  // Only the programs with virtual includes ("lab/..."); the fast and brute-force blurs have none.
  bool ok = true;
  for (ReloadableProgram* p : {&moments_, &blur_x_, &blur_y_, &debug_}) {
    ProgramDesc d = p->desc();
    d.includes = includes;
    d.rules = rules;
    p->set_desc(std::move(d));
    ok = p->rebuild() && ok;
  }
  return mask_.follow(moments_.desc()) && ok;
}

void MomentsPass::set_host_code(const GlHostCode& code) {
  if (code.create_moments_target == code_.create_moments_target && code.begin_moments_pass == code_.begin_moments_pass &&
      code.create_blur_target == code_.create_blur_target && code.run_blur_passes == code_.run_blur_passes)
    return;
  code_ = code;
  size_ = 0;  // made again, by the new code, before the next map
}

bool MomentsPass::ensure_targets(int size, const std::string& format, bool blur) {
  bool changed = false;
  const bool four = warp_exponent_ != 0.0f;
  if (size != size_ || format != format_ || four != four_moments_) {
    // The course's VSM target, made by lab 3's GL solution (renderer/moments_target.h).
    const MomentsTarget target = code_.create_moments_target(size, moments_format(format, four));
    moments_texture_ = GlTexture::adopt(target.moments_texture);
    depth_ = GlRenderbuffer::adopt(target.depth_renderbuffer);
    moments_fbo_ = GlFramebuffer::adopt(target.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, moments_fbo_.id());
    if (code_.own_moments_target()) check_framebuffer("moments");
    else say_incomplete_target("moments", "create_moments_target");
    blur_texture_ = {};  // reallocated below at the new size if needed
    blur_fbo_ = {};
    size_ = size;
    format_ = format;
    four_moments_ = four;
    changed = true;
  }
  if (blur && !blur_texture_) {
    // Lab 5's GL solution makes it (renderer/blur_passes.h): the moments' format and size, linear, clamped.
    const BlurTarget target = code_.create_blur_target(size_, moments_format(format_, four_moments_));
    blur_texture_ = GlTexture::adopt(target.texture);
    blur_fbo_ = GlFramebuffer::adopt(target.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, blur_fbo_.id());
    if (code_.own_moments_target()) check_framebuffer("blur");
    else say_incomplete_target("blur", "create_blur_target");
    changed = true;
  } else if (!blur && blur_texture_) {
    blur_texture_ = {};
    blur_fbo_ = {};
    changed = true;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return changed;
}

void MomentsPass::draw_moments(const GpuScene& scene, const glm::mat4& light_view_proj, int cull, bool cull_casters,
                               long& draws, long& culled) {
  if (moments_u_.generation != moments_.generation())
    moments_u_ = {moments_.generation(), Uniform(moments_.id(), "u_light_view_proj"),
                  Uniform(moments_.id(), "u_warp_exponent"), Uniform(moments_.id(), "u_warp_negative_exponent")};
  // Bound, the whole map in the viewport, cleared to (1, 1, 0, 0) and depth 1 (lab 3's GL solution); EVSM's
  // warped moments clear the colour once more to their far plane's.
  code_.begin_moments_pass({moments_fbo_.id(), moments_texture_.id(), depth_.id(), size_});
  if (warp_exponent_ != 0.0f) {
    const std::array<float, 4> clear = moments_clear(warp_exponent_, negative_exponent_);
    glClearBufferfv(GL_COLOR, 0, clear.data());
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  set_shadow_culling(cull);
  glUseProgram(moments_.id());
  moments_u_.light_view_proj.set(light_view_proj);
  moments_u_.warp_exponent.set(warp_exponent_);
  moments_u_.negative_exponent.set(negative_exponent_);
  const auto counts = scene.draw_casters(&light_view_proj, 1, cull_casters, mask_.prepare(scene, [&](AlphaMaskVariant& v) {
    v.set("u_light_view_proj", light_view_proj);
    v.set("u_warp_exponent", warp_exponent_);
    v.set("u_warp_negative_exponent", negative_exponent_);
  }));
  draws += counts.drawn;
  culled += counts.culled;
  glDisable(GL_CULL_FACE);
}

namespace {

// The Gaussian over the moments: vsm.blur_radius and vsm.blur_sigma, or with vsm.match_light (and a
// light to match, `matched` >= 0) the radius of a box as wide as the penumbra and that box's spread.
struct MomentsBlur {
  int radius = 0;
  float sigma = 1.0f;
};
MomentsBlur moments_blur(const ParamSet& params, int matched) {
  if (matched >= 0 && params.get(param::vsm_match_light))
    return {matched, std::max(0.25f, static_cast<float>(2 * matched + 1) / std::sqrt(12.0f))};
  return {params.get(param::vsm_blur_radius), params.get(param::vsm_blur_sigma)};
}

}  // namespace

bool MomentsPass::ensure_targets(const ParamSet& params) {
  const bool blur = moments_blur(params, matched_radius_).radius > 0;
  const glm::vec2 c = evsm_exponents(params);
  set_warp_exponent(c.x, c.y);
  return ensure_targets(std::stoi(params.get(param::shadow_map_size)), params.get(param::vsm_format), blur);
}

void MomentsPass::frame_inputs(PassContext& ctx, std::vector<float>& out) {
  // A blur matched to the light follows light.size (and the light's box), which the map's declared
  // inputs do not include.
  out.clear();
  if (ctx.params.get(param::vsm_match_light)) out.push_back(static_cast<float>(matched_radius_));
}

void MomentsPass::draw_map(PassContext& ctx) {
  // 1. The moments (z, z^2 + slope term) of the nearest surface per texel.
  ctx.timed("moments", [&] {
    ctx.count_texels([&] {
      draw_moments(ctx.gpu_scene, ctx.light.view.view_projection(), ctx.cull, ctx.params.get(param::shadow_cull_casters),
                   ctx.stats.draws, ctx.stats.casters_culled);
    });
  });
  ++ctx.stats.moments_passes;
  // 2. The Gaussian over the moments. Radius 0 runs none (and ensure_targets allocated no ping-pong
  // texture).
  const MomentsBlur b = moments_blur(ctx.params, matched_radius_);
  // Four moments (EVSM) are blurred by the taught separable shader, a pair at a time (blur()): the fast and
  // brute-force blurs read and write two channels.
  if (b.radius > 0)
    blur_map(ctx, b.radius, b.sigma,
             four_moments_ ? BlurMethod::Separable : blur_method_from_name(ctx.params.get(param::vsm_blur_method)));
  // Half floats run out of precision on large depth ranges: measure it so that it can be shown.
  // (Of depths only: warped moments have another background and scale.)
  ctx.stats.moments_negative_variance =
      format_ == "RG16F" && warp_exponent_ == 0.0f ? negative_variance_share(read_moments()) : -1.0;
}

void MomentsPass::blur_map(PassContext& ctx, int radius, float sigma, BlurMethod method) {
  // X then Y (the taught shader or the fast one), or one 2D pass and its copy back into A (brute2d,
  // timed together as "blur_2d"). Every blur writes the whole map once per direction (brute 2D: once,
  // and once more copying back).
  ctx.stats.shadow_texels_written += 2 * static_cast<long>(size_) * size_;
  if (method == BlurMethod::Brute2D) {
    ctx.timed("blur_2d", [&] { blur_brute2d(radius, sigma, ctx.empty_vao); });
    ctx.stats.blur_passes += 1;
    return;
  }
  if (method == BlurMethod::Fast) {
    for (int direction : {0, 1})
      ctx.timed(direction == 0 ? "blur_x" : "blur_y", [&] { blur_fast(direction, radius, sigma, ctx.empty_vao); });
  } else {
    blur(radius, sigma, ctx.empty_vao,
         [&](int pass, const std::function<void()>& draw) { ctx.timed(pass == 0 ? "blur_x" : "blur_y", draw); });
  }
  ctx.stats.blur_passes += 2;
}

glm::vec2 evsm_exponents(const ParamSet& params) {
  if (params.get(param::vsm_warp) != "exponential") return glm::vec2(0.0f);
  const float limit = params.get(param::vsm_format) == "RG16F" ? kEvsmMaxExponentRG16F : kEvsmMaxExponentRG32F;
  return {std::clamp(params.get(param::vsm_evsm_exponent), 0.0f, limit),
          std::clamp(params.get(param::vsm_evsm_negative_exponent), 0.0f, limit)};
}

float evsm_exponent(const ParamSet& params) { return evsm_exponents(params).x; }

std::array<float, 4> moments_clear(float warp_exponent, float negative_exponent) {
  if (warp_exponent == 0.0f) return {kMomentsClear[0], kMomentsClear[1], kMomentsClear[2], kMomentsClear[3]};
  const double cp = warp_exponent, cn = negative_exponent;
  return {static_cast<float>(std::exp(cp)), static_cast<float>(std::exp(2.0 * cp)), static_cast<float>(-std::exp(-cn)),
          static_cast<float>(std::exp(-2.0 * cn))};
}

LitBind MomentsPass::lit_bind(GLuint program) const {
  struct Uniforms {
    Uniform warp_exponent, negative_exponent, min_variance, bleed_delta;
  };
  const Uniforms u{Uniform(program, "u_warp_exponent"), Uniform(program, "u_warp_negative_exponent"),
                   Uniform(program, "u_min_variance"), Uniform(program, "u_bleed_delta")};
  return [this, u](const ParamSet& params) {
    const glm::vec2 c = evsm_exponents(params);
    u.warp_exponent.set(c.x);
    u.negative_exponent.set(c.y);
    u.min_variance.set(params.get(param::vsm_min_variance));
    u.bleed_delta.set(params.get(param::vsm_bleed_delta));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, moments_texture_.id());
  };
}

std::optional<LitView> MomentsPass::lit_view(const ParamSet& params) const {
  if (!params.get(param::vsm_show_remap)) return std::nullopt;
  return LitView{{LitVariant::Overlay, "remap_view"}, remap_view_legend()};
}

void MomentsPass::draw_debug_quads(const DebugQuadArea& area) {
  // "all": E[z], E[z^2] and the variance left to right; else the one channel ("depth" is E[z]).
  const int only = area.channel == "moment 2" ? 1 : area.channel == "variance" ? 2 : area.channel == "all" ? -1 : 0;
  const int count = only < 0 ? 3 : 1;
  // With the warps (EVSM) the quads show the positive warp's moments, of w+ = exp(c+ z).
  const bool warped = warp_exponent_ != 0.0f;
  const char* labels[3] = {warped ? "positive warp: E[w+]" : "moments: E[z]",
                           warped ? "positive warp: E[w+²]" : "moments: E[z²]",
                           warped ? "variance E[w+²] - E[w+]² (red: negative)" : "variance E[z²] - E[z]² (red: negative)"};
  for (int i = 0; i < count; ++i) {
    const int channel = only < 0 ? i : only;
    area.place(area.width - (count - i) * (area.side + 8), 8, area.side, area.side, labels[channel]);
    draw_debug_quad(channel, area.empty_vao);
  }
}

std::vector<std::uint8_t> MomentsPass::image(int* size) const {
  const std::vector<float> depth = read_depth(size);  // sets *size
  return depth_map_image(depth, *size);
}

void MomentsPass::set_fast_path(FastPath path) {
  if (path == FastPath::Compute && !has_compute_shaders())
    throw std::logic_error("the fast blur's compute path needs OpenGL 4.3");
  fast_path_ = path;
}

void MomentsPass::draw_debug_quad(int channel, GLuint empty_vao) {
  if (debug_u_.generation != debug_.generation())
    debug_u_ = {debug_.generation(), Uniform(debug_.id(), "u_moments"), Uniform(debug_.id(), "u_channel"),
                Uniform(debug_.id(), "u_warp_exponent")};
  glUseProgram(debug_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, moments_texture_.id());
  debug_u_.moments.set(0);
  debug_u_.channel.set(channel);
  debug_u_.warp_exponent.set(warp_exponent_);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

double MomentsPass::negative_variance_share(const std::vector<float>& moments) {
  long covered = 0, negative = 0;
  for (std::size_t i = 0; i + 1 < moments.size(); i += 2) {
    if (!(moments[i] < 1.0f)) continue;  // background (cleared to 1, 1)
    ++covered;
    if (moments[i + 1] - moments[i] * moments[i] < 0.0f) ++negative;
  }
  return covered ? static_cast<double>(negative) / static_cast<double>(covered) : 0.0;
}

std::vector<float> MomentsPass::read_moments() const {
  return read_pixels(moments_fbo_.id(), GL_COLOR_ATTACHMENT0, size_, size_, GL_RG, 2);
}

std::vector<float> MomentsPass::read_depth(int* size) const {
  *size = size_;
  return read_pixels(moments_fbo_.id(), GL_NONE, size_, size_, GL_DEPTH_COMPONENT, 1);
}

MomentsTargetInfo MomentsPass::query_targets() const {
  MomentsTargetInfo info;
  info.size = size_;
  info.blur_target = static_cast<bool>(blur_texture_);
  if (!moments_texture_) return info;
  glBindTexture(GL_TEXTURE_2D, moments_texture_.id());
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &info.internal_format);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &info.min_filter);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &info.mag_filter);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &info.wrap_s);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &info.wrap_t);
  glBindFramebuffer(GL_FRAMEBUFFER, moments_fbo_.id());
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &info.color_attachment_type);
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                        &info.depth_attachment_type);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &info.depth_internal_format);
  return info;
}

}  // namespace shadowlab
