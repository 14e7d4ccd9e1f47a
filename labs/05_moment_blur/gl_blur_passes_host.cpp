// main() of lab 5's GL exercise when grading builds it (grading/cpp_exercise.h, `renders`): a headless
// OpenGL context first, then each BlurCall is answered with what create_blur_target and run_blur_passes
// did (labs/05_moment_blur/gl_setup.h). Not part of the shadowlab binary.
#include <vector>

#include "labs/05_moment_blur/gl_setup.h"
#include "grading/cpp_exercise_host.h"
#include "grading/gl_exercise_host.h"

namespace {

using namespace shadowlab;

// The blur each pass runs: the separable Gaussian of lab 5 (shaders/vsm/gaussian_blur.glsl), reading
// with texture() at texel centres as a one-shader blur with a direction uniform does, so that the
// direction, the texel size and the target's wrap all decide what it reads.
constexpr const char* kVertex =
    "#version 330 core\n"
    "void main() { gl_Position = vec4(vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0, 0.0, 1.0); }\n";
constexpr const char* kBlur =
    "#version 330 core\n"
    "uniform sampler2D u_moments;\nuniform vec2 u_direction;\nuniform vec2 u_texel_size;\n"
    "uniform int u_blur_radius;\nuniform float u_blur_sigma;\nout vec4 o_moments;\n"
    "void main() {\n"
    "  vec2 uv = gl_FragCoord.xy * u_texel_size;\n"
    "  vec2 sum = vec2(0.0);\n  float weight_sum = 0.0;\n"
    "  for (int i = -u_blur_radius; i <= u_blur_radius; ++i) {\n"
    "    float w = exp(-float(i * i) / (2.0 * u_blur_sigma * u_blur_sigma));\n"
    "    sum += w * texture(u_moments, uv + float(i) * u_direction * u_texel_size).rg;\n"
    "    weight_sum += w;\n  }\n"
    "  o_moments = vec4(sum / weight_sum, 0.0, 1.0);\n}\n";

void read_target(const BlurTarget& target, BlurState& s) {
  s.size = target.size;
  s.framebuffer = static_cast<int>(target.framebuffer);
  s.texture = static_cast<int>(target.texture);
  s.is_framebuffer = glIsFramebuffer(target.framebuffer);
  s.is_texture = glIsTexture(target.texture);
  if (s.is_texture) {
    glBindTexture(GL_TEXTURE_2D, target.texture);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &s.internal_format);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &s.width);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &s.height);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE, &s.red_type);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &s.red_bits);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &s.min_filter);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &s.mag_filter);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &s.wrap_s);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &s.wrap_t);
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  if (s.is_framebuffer) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer);
    s.status = static_cast<int>(glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                          &s.colour_attachment_type);
    if (s.colour_attachment_type == GL_TEXTURE)
      glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME,
                                            &s.colour_attachment_name);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
}

// The state one job.draw sees (it changes nothing the student set).
BlurDraw record_draw(int pass) {
  BlurDraw d;
  d.pass = pass;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &d.framebuffer);
  if (d.framebuffer != 0) {
    GLint type = GL_NONE;
    glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                          &type);
    if (type == GL_TEXTURE)
      glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &d.writes);
  }
  glGetIntegerv(GL_VIEWPORT, d.viewport);
  d.depth_test = glIsEnabled(GL_DEPTH_TEST);
  glGetIntegerv(GL_CURRENT_PROGRAM, &d.program);
  const auto program = static_cast<GLuint>(d.program);
  if (program == 0 || !glIsProgram(program)) return d;
  glGetUniformiv(program, glGetUniformLocation(program, "u_moments"), &d.unit);
  glGetUniformfv(program, glGetUniformLocation(program, "u_direction"), d.direction);
  glGetUniformfv(program, glGetUniformLocation(program, "u_texel_size"), d.texel_size);
  if (d.unit < 0 || d.unit >= 16) return d;  // GL 3.3 has at least 16 units per stage
  GLint active = GL_TEXTURE0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(d.unit));
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &d.reads);
  glActiveTexture(static_cast<GLenum>(active));
  return d;
}

// A size x size RG texture's texels through a framebuffer with it as colour attachment 0.
void read_texels(GLuint framebuffer, int size, float* out) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size, size, GL_RG, GL_FLOAT, out);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

struct Moments {
  GLuint texture = 0, depth = 0, framebuffer = 0;
};

// The moments to blur (blur_input), with a depth buffer as the moments pass leaves it: kBlurStainDepth
// over the left half, 1 over the right.
Moments make_moments(int size) {
  Moments m;
  std::vector<float> texels;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 2; ++c) texels.push_back(blur_input(size, x, y, c));
  glGenTextures(1, &m.texture);
  glBindTexture(GL_TEXTURE_2D, m.texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, size, size, 0, GL_RG, GL_FLOAT, texels.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenRenderbuffers(1, &m.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, m.depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
  glGenFramebuffers(1, &m.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, m.framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m.texture, 0);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, m.depth);
  glDepthMask(GL_TRUE);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, size / 2, size);
  glClearDepth(kBlurStainDepth);
  glClear(GL_DEPTH_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glClearDepth(1.0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return m;
}

BlurState answer(const BlurCall& call) {
  BlurState s;
  const int size = call.size;
  if (size < 1 || size > kBlurMaxSize) return s;
  while (glGetError() != GL_NO_ERROR) {
  }
  const BlurTarget target = create_blur_target(size, GL_RG32F);
  s.gl_error_after_create = static_cast<int>(glGetError());
  read_target(target, s);
  const Moments m = make_moments(size);
  const GLuint program_x = compile_exercise_program(kVertex, kBlur), program_y = compile_exercise_program(kVertex, kBlur);
  for (const GLuint program : {program_x, program_y}) {
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "u_blur_radius"), call.radius);
    glUniform1f(glGetUniformLocation(program, "u_blur_sigma"), call.sigma);
  }
  GLuint vao = 0, decoy = 0;
  glGenVertexArrays(1, &vao);
  // The frame's state before the blur: the window's framebuffer and viewport, the moments pass's depth
  // test, no program, and on unit 0 a texture that is no moments (a pass that binds none reads it).
  const float decoy_texel[2] = {7.0f, 7.0f};
  glGenTextures(1, &decoy);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, decoy);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, 1, 1, 0, GL_RG, GL_FLOAT, decoy_texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, call.window_width, call.window_height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  s.moments_texture = static_cast<int>(m.texture);
  s.moments_framebuffer = static_cast<int>(m.framebuffer);
  s.program_x = static_cast<int>(program_x);
  s.program_y = static_cast<int>(program_y);
  while (glGetError() != GL_NO_ERROR) {
  }
  BlurJob job{m.texture, m.framebuffer, size, target, program_x, program_y, {}};
  job.draw = [&](int pass) {
    // The student's first error is kept; the queries' own (on a program not the host's) are dropped.
    const GLenum before = glGetError();
    if (s.gl_error_after_run == GL_NO_ERROR) s.gl_error_after_run = static_cast<int>(before);
    if (s.draws < kBlurMaxDraws) s.draw[s.draws] = record_draw(pass);
    while (glGetError() != GL_NO_ERROR) {
    }
    ++s.draws;
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  };
  run_blur_passes(job);
  if (s.gl_error_after_run == GL_NO_ERROR) s.gl_error_after_run = static_cast<int>(glGetError());
  glDisable(GL_DEPTH_TEST);
  read_texels(m.framebuffer, size, s.moments);
  if (s.status == GL_FRAMEBUFFER_COMPLETE && s.width == size && s.height == size)
    read_texels(target.framebuffer, size, s.intermediate);
  else
    s.intermediate[0] = -1e30f;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  for (const GLuint program : {program_x, program_y}) glDeleteProgram(program);
  glDeleteVertexArrays(1, &vao);
  glDeleteTextures(1, &decoy);
  glDeleteFramebuffers(1, &m.framebuffer);
  glDeleteRenderbuffers(1, &m.depth);
  glDeleteTextures(1, &m.texture);
  glDeleteFramebuffers(1, &target.framebuffer);
  glDeleteTextures(1, &target.texture);
  return s;
}

}  // namespace

int main() { return serve_exercise<BlurCall, BlurState>(answer, make_exercise_gl_context); }
