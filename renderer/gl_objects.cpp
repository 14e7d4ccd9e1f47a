#include "renderer/gl_objects.h"

#include <array>
#include <atomic>
#include <sstream>
#include <stdexcept>

namespace shadowlab {
namespace {
std::array<std::atomic<int>, static_cast<int>(GlKind::Count)> live_counts{};
}

const char* gl_kind_name(GlKind kind) {
  static constexpr const char* names[] = {"buffer", "vertex array", "texture", "framebuffer",
                                          "renderbuffer", "shader", "program", "query", "sampler"};
  return names[static_cast<int>(kind)];
}

int live_gl_objects(GlKind kind) { return live_counts[static_cast<int>(kind)].load(); }

int live_gl_objects() {
  int total = 0;
  for (const auto& c : live_counts) total += c.load();
  return total;
}

GlTexture make_texture_2d(GLenum internal_format, int width, int height, GLenum format, GLenum type, GLenum filter) {
  GlTexture t = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

std::vector<float> read_pixels(GLuint framebuffer, GLenum attachment, int width, int height, GLenum format, int channels) {
  std::vector<float> data(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                          static_cast<std::size_t>(channels));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  if (attachment != GL_NONE) glReadBuffer(attachment);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, format, GL_FLOAT, data.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return data;
}

GlSampler make_compare_sampler() {
  GlSampler s = GlSampler::create();
  glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return s;
}

void bind_color_target(GLuint framebuffer, int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  const GLenum color = framebuffer == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0;  // 0: the window's
  glDrawBuffers(1, &color);
  glViewport(0, 0, width, height);
}

void check_framebuffer(const char* what) {
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    std::ostringstream s;
    s << what << " framebuffer is incomplete (status 0x" << std::hex << status << ")";
    throw std::runtime_error(s.str());
  }
}

namespace detail {

void note_created(GlKind kind) { ++live_counts[static_cast<int>(kind)]; }

GLuint generate(GlKind kind) {
  GLuint id = 0;
  switch (kind) {
    case GlKind::Buffer: glGenBuffers(1, &id); break;
    case GlKind::VertexArray: glGenVertexArrays(1, &id); break;
    case GlKind::Texture: glGenTextures(1, &id); break;
    case GlKind::Framebuffer: glGenFramebuffers(1, &id); break;
    case GlKind::Renderbuffer: glGenRenderbuffers(1, &id); break;
    case GlKind::Program: id = glCreateProgram(); break;
    case GlKind::Query: glGenQueries(1, &id); break;
    case GlKind::Sampler: glGenSamplers(1, &id); break;
    case GlKind::Shader:
    case GlKind::Count: break;  // shaders need a type: make_shader()
  }
  if (id != 0) note_created(kind);
  return id;
}

void destroy(GlKind kind, GLuint id) {
  switch (kind) {
    case GlKind::Buffer: glDeleteBuffers(1, &id); break;
    case GlKind::VertexArray: glDeleteVertexArrays(1, &id); break;
    case GlKind::Texture: glDeleteTextures(1, &id); break;
    case GlKind::Framebuffer: glDeleteFramebuffers(1, &id); break;
    case GlKind::Renderbuffer: glDeleteRenderbuffers(1, &id); break;
    case GlKind::Shader: glDeleteShader(id); break;
    case GlKind::Program: glDeleteProgram(id); break;
    case GlKind::Query: glDeleteQueries(1, &id); break;
    case GlKind::Sampler: glDeleteSamplers(1, &id); break;
    case GlKind::Count: return;
  }
  --live_counts[static_cast<int>(kind)];
}

}  // namespace detail
}  // namespace shadowlab
