// Move-only owners for every kind of GL object, with a live count per kind that tests read (it must be
// 0 after shutdown). A default-constructed owner holds nothing; a moved-from owner holds nothing.
#pragma once

#include <utility>
#include <vector>

#include "renderer/gl.h"

namespace shadowlab {

enum class GlKind { Buffer, VertexArray, Texture, Framebuffer, Renderbuffer, Shader, Program, Query, Sampler, Count };

const char* gl_kind_name(GlKind kind);
int live_gl_objects();
int live_gl_objects(GlKind kind);

namespace detail {
void note_created(GlKind kind);
void destroy(GlKind kind, GLuint id);
GLuint generate(GlKind kind);  // for the kinds made by glGen*/glCreateProgram
}  // namespace detail

template <GlKind K>
class GlObject {
 public:
  GlObject() = default;
  // Makes a new object of this kind (not for shaders, which need a type: see make_shader).
  static GlObject create() { return GlObject(detail::generate(K)); }
  // Takes ownership of an id made elsewhere (glCreateShader).
  static GlObject adopt(GLuint id) {
    detail::note_created(K);
    return GlObject(id);
  }

  ~GlObject() { reset(); }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) detail::destroy(K, std::exchange(id_, 0));
  }

 private:
  explicit GlObject(GLuint id) : id_(id) {}
  GLuint id_ = 0;
};

using GlBuffer = GlObject<GlKind::Buffer>;
using GlVertexArray = GlObject<GlKind::VertexArray>;
using GlTexture = GlObject<GlKind::Texture>;
using GlFramebuffer = GlObject<GlKind::Framebuffer>;
using GlRenderbuffer = GlObject<GlKind::Renderbuffer>;
using GlShader = GlObject<GlKind::Shader>;
using GlProgram = GlObject<GlKind::Program>;
using GlQuery = GlObject<GlKind::Query>;
using GlSampler = GlObject<GlKind::Sampler>;

inline GlShader make_shader(GLenum type) { return GlShader::adopt(glCreateShader(type)); }

// A 2D texture with storage, one filter for min and mag, clamped to the edge.
GlTexture make_texture_2d(GLenum internal_format, int width, int height, GLenum format, GLenum type, GLenum filter);

// A sampler for sampler2DShadow reads: GL_COMPARE_REF_TO_TEXTURE (LEQUAL), linear (the four nearest
// comparisons filtered bilinearly), clamped to the edge.
GlSampler make_compare_sampler();

// Throws "<what> framebuffer is incomplete (status 0x...)" unless the bound framebuffer is complete.
void check_framebuffer(const char* what);
// Reads a width x height block of floats (`channels` per pixel, GL's `format`) from a framebuffer's
// attachment, bottom row first; `attachment` GL_NONE reads depth (format GL_DEPTH_COMPONENT).
std::vector<float> read_pixels(GLuint framebuffer, GLenum attachment, int width, int height, GLenum format, int channels);

// Binds a framebuffer to draw into its first colour attachment only (a G-buffer's other attachments
// keep what they hold) over a width x height viewport.
void bind_color_target(GLuint framebuffer, int width, int height);

}  // namespace shadowlab
