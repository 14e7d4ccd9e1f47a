#include "app/bench_baseline.h"

#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace shadowlab {

namespace {

// The tutorial's shaders, reduced to what the lab's frame computes too: ambient + Lambert, the light's
// term scaled by 1 - shadow, the slope-scaled bias max(0.05 (1 - n.l), 0.005), PCF over 3 x 3 texels.
constexpr const char* kDepthVert = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }
)";
constexpr const char* kDepthFrag = R"(#version 330 core
void main() {}
)";
constexpr const char* kLitVert = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
uniform mat4 u_view_proj;
uniform mat4 u_light_view_proj;
out vec3 v_normal;
out vec3 v_color;
out vec4 v_light_clip;
void main() {
  v_normal = a_normal;
  v_color = a_color;
  v_light_clip = u_light_view_proj * vec4(a_position, 1.0);
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
)";
constexpr const char* kLitFrag = R"(#version 330 core
in vec3 v_normal;
in vec3 v_color;
in vec4 v_light_clip;
uniform vec3 u_to_light;
uniform sampler2D u_shadow_map;
out vec4 frag_color;
float shadow(float n_dot_l) {
  vec3 p = v_light_clip.xyz / v_light_clip.w * 0.5 + 0.5;
  if (p.z > 1.0) return 0.0;
  float bias = max(0.05 * (1.0 - n_dot_l), 0.005);
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  float s = 0.0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      s += p.z - bias > texture(u_shadow_map, p.xy + vec2(x, y) * texel).r ? 1.0 : 0.0;
  return s / 9.0;
}
void main() {
  vec3 n = normalize(v_normal);
  float n_dot_l = max(dot(n, u_to_light), 0.0);
  vec3 c = v_color * (0.3 + (1.0 - shadow(n_dot_l)) * n_dot_l);
  frag_color = vec4(c, 1.0);
}
)";

GlProgram link(const char* vert, const char* frag) {
  GlProgram program = GlProgram::adopt(glCreateProgram());
  for (const auto& [type, source] : {std::pair{GL_VERTEX_SHADER, vert}, std::pair{GL_FRAGMENT_SHADER, frag}}) {
    GlShader shader = make_shader(type);
    glShaderSource(shader.id(), 1, &source, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
      char log[2048] = {};
      glGetShaderInfoLog(shader.id(), sizeof log, nullptr, log);
      throw std::runtime_error(std::string("the bare two-pass baseline's shader does not compile: ") + log);
    }
    glAttachShader(program.id(), shader.id());
  }
  glLinkProgram(program.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("the bare two-pass baseline's program does not link");
  return program;
}

Mesh cube(const glm::mat4& transform, const glm::vec3& color) {
  Mesh m = make_box(glm::vec3(0.0f), glm::vec3(1.0f), color);
  transform_mesh(m, transform);
  return m;
}

}  // namespace

Scene make_learnopengl_scene() {
  Scene s;
  s.name = "learnopengl";
  Mesh floor = make_plane({0.0f, -0.5f, 0.0f}, 25.0f, 25.0f, {0.75f, 0.75f, 0.72f});
  floor.name = "floor";
  s.meshes.push_back(std::move(floor));
  const glm::mat4 one(1.0f);
  const glm::vec3 color(0.8f, 0.55f, 0.35f);
  s.meshes.push_back(cube(glm::scale(glm::translate(one, {0.0f, 1.5f, 0.0f}), glm::vec3(0.5f)), color));
  s.meshes.push_back(cube(glm::scale(glm::translate(one, {2.0f, 0.0f, 1.0f}), glm::vec3(0.5f)), color));
  s.meshes.push_back(cube(glm::scale(glm::rotate(glm::translate(one, {-1.0f, 0.0f, 2.0f}), glm::radians(60.0f),
                                                 glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f))),
                                     glm::vec3(0.25f)),
                          color));
  for (std::size_t i = 1; i < s.meshes.size(); ++i) s.meshes[i].name = "cube " + std::to_string(i);
  return s;
}

BareTwoPass::BareTwoPass(const Scene& scene, int map_size)
    : scene_(scene),
      map_size_(map_size),
      depth_(make_texture_2d(GL_DEPTH_COMPONENT24, map_size, map_size, GL_DEPTH_COMPONENT, GL_FLOAT, GL_NEAREST)),
      fbo_(GlFramebuffer::create()),
      depth_program_(link(kDepthVert, kDepthFrag)),
      lit_program_(link(kLitVert, kLitFrag)) {
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  const float white[] = {1.0f, 1.0f, 1.0f, 1.0f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, white);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_.id(), 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  check_framebuffer("the bare baseline's shadow map");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  depth_mvp_ = glGetUniformLocation(depth_program_.id(), "u_mvp");
  lit_vp_ = glGetUniformLocation(lit_program_.id(), "u_view_proj");
  lit_light_vp_ = glGetUniformLocation(lit_program_.id(), "u_light_view_proj");
  lit_to_light_ = glGetUniformLocation(lit_program_.id(), "u_to_light");
  lit_map_ = glGetUniformLocation(lit_program_.id(), "u_shadow_map");
}

void BareTwoPass::draw(const glm::mat4& light_view_proj, const glm::vec3& to_light, const glm::mat4& camera_view_proj,
                       GLuint framebuffer, int width, int height) const {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  scene_.bind();
  // 1. Depth from the light.
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, map_size_, map_size_);
  glClear(GL_DEPTH_BUFFER_BIT);
  glUseProgram(depth_program_.id());
  glUniformMatrix4fv(depth_mvp_, 1, GL_FALSE, glm::value_ptr(light_view_proj));
  for (const auto& range : scene_.ranges()) scene_.draw(range);
  // 2. Lit from the camera.
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glClearColor(0.16f, 0.18f, 0.22f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(lit_program_.id());
  glUniformMatrix4fv(lit_vp_, 1, GL_FALSE, glm::value_ptr(camera_view_proj));
  glUniformMatrix4fv(lit_light_vp_, 1, GL_FALSE, glm::value_ptr(light_view_proj));
  glUniform3fv(lit_to_light_, 1, glm::value_ptr(to_light));
  glUniform1i(lit_map_, 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, depth_.id());
  for (const auto& range : scene_.ranges()) scene_.draw(range);
  glUseProgram(0);
}

}  // namespace shadowlab
