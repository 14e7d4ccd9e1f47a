#include "labs/probe.h"

#include <algorithm>
#include <stdexcept>

#include "labs/lab.h"
#include "renderer/gl_objects.h"
#include "renderer/shader.h"

namespace shadowlab {

namespace {

constexpr int kRowWidth = 256;  // cases per row of the probe's textures
constexpr int kInputUnit0 = 6, kInputUnit1 = 7;

GlTexture input_texture(const std::vector<glm::vec4>& values, int width, int height) {
  std::vector<glm::vec4> padded(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), glm::vec4(0.0f));
  std::copy(values.begin(), values.end(), padded.begin());
  GlTexture t = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, t.id());
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, padded.data());
  return t;
}

}  // namespace

void set_uniform(GLuint program, const char* name, float value) { glUniform1f(glGetUniformLocation(program, name), value); }
void set_uniform(GLuint program, const char* name, int value) { glUniform1i(glGetUniformLocation(program, name), value); }
void set_uniform(GLuint program, const char* name, const glm::mat4& value) {
  glUniformMatrix4fv(glGetUniformLocation(program, name), 1, GL_FALSE, &value[0][0]);
}
void set_uniform(GLuint program, const char* name, const glm::vec3& value) {
  glUniform3f(glGetUniformLocation(program, name), value.x, value.y, value.z);
}

std::vector<float> run_probe(const LabHooks& hooks, const ProbeRequest& request) {
  const std::size_t cases = request.in0.size();
  if (cases == 0) return {};
  if (!request.in1.empty() && request.in1.size() != cases) throw std::invalid_argument("probe: in0 and in1 differ in size");
  ProgramDesc desc{"shaders/fullscreen.vert", {}, request.fragment, {}, {}, hooks.include_rules};
  for (const auto& [name, file] : Renderer::default_includes(hooks.technique, hooks.light.value_or(LightType::Directional)))
    desc.includes[name] = file;
  for (const auto& [name, file] : hooks.includes) desc.includes[name] = file;
  ProgramBuild build = build_program(desc);
  if (!build.program) throw BuildError(build.error);

  const int width = static_cast<int>(std::min<std::size_t>(cases, kRowWidth));
  const int height = static_cast<int>((cases + kRowWidth - 1) / kRowWidth);
  GlTexture in0 = input_texture(request.in0, width, height);
  GlTexture in1 = input_texture(request.in1.empty() ? std::vector<glm::vec4>{} : request.in1, width, height);
  GlTexture out = make_texture_2d(GL_RGBA32F, width, height, GL_RGBA, GL_FLOAT, GL_NEAREST);
  GlFramebuffer fbo = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out.id(), 0);
  check_framebuffer("probe");
  GlVertexArray vao = GlVertexArray::create();

  const GLuint program = build.program.id();
  glUseProgram(program);
  glActiveTexture(GL_TEXTURE0 + kInputUnit0);
  glBindTexture(GL_TEXTURE_2D, in0.id());
  set_uniform(program, "u_probe_in0", kInputUnit0);
  glActiveTexture(GL_TEXTURE0 + kInputUnit1);
  glBindTexture(GL_TEXTURE_2D, in1.id());
  set_uniform(program, "u_probe_in1", kInputUnit1);
  glActiveTexture(GL_TEXTURE0);
  if (request.set_uniforms) request.set_uniforms(program);

  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(vao.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<glm::vec4> result(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, result.data());
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  for (int unit : {0, 1, 2, 3, kInputUnit0, kInputUnit1}) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindSampler(static_cast<GLuint>(unit), 0);
  }
  glActiveTexture(GL_TEXTURE0);

  std::vector<float> values(cases);
  for (std::size_t i = 0; i < cases; ++i) values[i] = result[i].x;
  return values;
}

}  // namespace shadowlab
