#include "renderer/moments_pass.h"

#include <sstream>
#include <stdexcept>

namespace shadowlab {

namespace {

GlTexture make_moments_texture(GLenum internal_format, int size) {
  GlTexture t = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), size, size, 0, GL_RG, GL_FLOAT, nullptr);
  // Linear filtering is what VSM is for: the average of moments is still a pair of moments, while the
  // average of depths compared with one depth means nothing.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

GlFramebuffer make_color_fbo(GLuint texture, GLuint depth_renderbuffer, const char* what) {
  GlFramebuffer fbo = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  if (depth_renderbuffer)
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_renderbuffer);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    std::ostringstream s;
    s << what << " framebuffer is incomplete (status 0x" << std::hex << status << ")";
    throw std::runtime_error(s.str());
  }
  return fbo;
}

ProgramDesc blur_desc(const char* direction) {
  return {"shaders/fullscreen.vert", {}, "shaders/vsm/blur.frag", {{"BLUR_DIRECTION", direction}}, {}};
}

}  // namespace

MomentsPass::MomentsPass()
    : moments_({"shaders/shadow_depth.vert", {}, "shaders/vsm/moments.frag", {}, {}}),
      blur_x_(blur_desc("ivec2(1, 0)")),
      blur_y_(blur_desc("ivec2(0, 1)")),
      debug_({"shaders/fullscreen.vert", {}, "shaders/vsm/debug_moments.frag", {}, {}}) {}

bool MomentsPass::set_includes(const std::map<std::string, std::filesystem::path>& includes) {
  bool ok = true;
  for_each_program([&](ReloadableProgram& p) {
    ProgramDesc d = p.desc();
    d.includes = includes;
    p.set_desc(std::move(d));
    ok = p.rebuild() && ok;
  });
  return ok;
}

bool MomentsPass::ensure_targets(int size, const std::string& format, bool blur) {
  bool changed = false;
  if (size != size_ || format != format_) {
    const GLenum internal_format = format == "RG16F" ? GL_RG16F : GL_RG32F;
    moments_texture_ = make_moments_texture(internal_format, size);
    depth_ = GlRenderbuffer::create();
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.id());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
    moments_fbo_ = make_color_fbo(moments_texture_.id(), depth_.id(), "moments");
    blur_texture_ = {};  // reallocated below at the new size if needed
    blur_fbo_ = {};
    size_ = size;
    format_ = format;
    changed = true;
  }
  if (blur && !blur_texture_) {
    const GLenum internal_format = format_ == "RG16F" ? GL_RG16F : GL_RG32F;
    blur_texture_ = make_moments_texture(internal_format, size_);
    blur_fbo_ = make_color_fbo(blur_texture_.id(), 0, "blur");
    changed = true;
  } else if (!blur && blur_texture_) {
    blur_texture_ = {};
    blur_fbo_ = {};
    changed = true;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return changed;
}

void MomentsPass::draw_moments(const GpuScene& scene, const glm::mat4& light_view_proj, int cull, long& draws) {
  if (moments_u_.generation != moments_.generation())
    moments_u_ = {moments_.generation(), Uniform(moments_.id(), "u_light_view_proj")};
  glBindFramebuffer(GL_FRAMEBUFFER, moments_fbo_.id());
  const GLenum color = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &color);
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glClearBufferfv(GL_COLOR, 0, kMomentsClear);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  if (cull == 0) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(cull == 1 ? GL_FRONT : GL_BACK);
  }
  glUseProgram(moments_.id());
  moments_u_.light_view_proj.set(light_view_proj);
  scene.bind();
  for (const auto& range : scene.ranges()) {
    if (!range.casts_shadow) continue;
    scene.draw(range);
    ++draws;
  }
  glDisable(GL_CULL_FACE);
}

void MomentsPass::blur(int direction, int radius, float sigma, GLuint empty_vao) {
  if (!blur_texture_) throw std::logic_error("MomentsPass::blur without a blur target");
  ReloadableProgram& program = direction == 0 ? blur_x_ : blur_y_;
  BlurUniforms& u = direction == 0 ? blur_x_u_ : blur_y_u_;
  if (u.generation != program.generation()) {
    const GLuint id = program.id();
    u = {program.generation(), Uniform(id, "u_moments"), Uniform(id, "u_blur_radius"), Uniform(id, "u_blur_sigma")};
  }
  // X reads A and writes B, Y reads B and writes A: a texture is never read and written at once.
  glBindFramebuffer(GL_FRAMEBUFFER, direction == 0 ? blur_fbo_.id() : moments_fbo_.id());
  const GLenum color = GL_COLOR_ATTACHMENT0;
  glDrawBuffers(1, &color);
  glViewport(0, 0, size_, size_);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(program.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, direction == 0 ? moments_texture_.id() : blur_texture_.id());
  u.moments.set(0);
  u.radius.set(radius);
  u.sigma.set(sigma);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
}

void MomentsPass::draw_debug_quad(int channel, GLuint empty_vao) {
  if (debug_u_.generation != debug_.generation())
    debug_u_ = {debug_.generation(), Uniform(debug_.id(), "u_moments"), Uniform(debug_.id(), "u_channel")};
  glUseProgram(debug_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, moments_texture_.id());
  debug_u_.moments.set(0);
  debug_u_.channel.set(channel);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

std::vector<float> MomentsPass::read_moments() const {
  std::vector<float> data(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_) * 2);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, moments_fbo_.id());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_, size_, GL_RG, GL_FLOAT, data.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return data;
}

std::vector<float> MomentsPass::read_depth() const {
  std::vector<float> data(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, moments_fbo_.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_, size_, GL_DEPTH_COMPONENT, GL_FLOAT, data.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return data;
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
