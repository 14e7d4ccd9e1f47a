#include "renderer/cube_shadow_pass.h"

#include <sstream>
#include <stdexcept>

namespace shadowlab {

namespace {

constexpr const char* kStoreInclude = "lab/cube_store.glsl";
constexpr const char* kDefaultStore = "shaders/cube/store.glsl";

// Six layers, one per cube face in GL's order.
GlTexture make_faces(GLenum internal_format, GLenum format, int size) {
  GlTexture t = GlTexture::create();
  glBindTexture(GL_TEXTURE_2D_ARRAY, t.id());
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, static_cast<GLint>(internal_format), size, size, 6, 0, format, GL_FLOAT, nullptr);
  // Nearest: a distance averaged across an object's outline is a distance where there is no surface.
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  return t;
}

}  // namespace

CubeShadowPass::CubeShadowPass()
    : faces_({"shaders/cube/distance.vert", {}, "shaders/cube/distance.frag", {}, {{kStoreInclude, kDefaultStore}}}),
      layered_({"shaders/cube/distance.vert", "shaders/cube/layers.geom", "shaders/cube/distance.frag",
                {{"LAYERED", "1"}}, {{kStoreInclude, kDefaultStore}}}) {
  if (!faces_.rebuild() || !layered_.rebuild())
    throw std::runtime_error("cannot build the cube shadow pass's shaders:\n" + faces_.error() + layered_.error());
}

bool CubeShadowPass::set_includes(const std::map<std::string, std::filesystem::path>& includes, const IncludeRules& rules) {
  bool ok = true;
  for (ReloadableProgram* p : {&faces_, &layered_}) {
    ProgramDesc d = p->desc();
    d.includes = includes;
    d.rules = rules;
    if (!d.includes.count(kStoreInclude)) d.includes[kStoreInclude] = kDefaultStore;
    p->set_desc(std::move(d));
    ok = p->rebuild() && ok;
  }
  return ok;
}

bool CubeShadowPass::ensure_targets(int size) {
  if (size == size_ && distance_) return false;
  distance_ = make_faces(GL_R32F, GL_RED, size);
  depth_ = make_faces(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, size);
  fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0);  // layered: all six layers
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  check_framebuffer("cube shadow (layered)");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  size_ = size;
  return true;
}

void CubeShadowPass::draw(const GpuScene& scene, const CubeLightViews& views, const glm::vec3& light_position,
                          bool single_pass, bool cull_casters, long& draws, long& faces, long& culled) {
  bind_color_target(fbo_.id(), size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  const float empty[4] = {kCubeEmptyDistance, 0.0f, 0.0f, 0.0f};
  const float far_depth = 1.0f;
  glm::mat4 view_proj[6];
  for (int f = 0; f < 6; ++f) view_proj[f] = views.projection * views.view[f];
  // A caster outside every face's frustum (single pass) or outside this face's (six passes) is not drawn.
  auto draw_casters = [&](const glm::mat4* faces_view_proj, int count) {
    const auto counts = scene.draw_casters(faces_view_proj, count, cull_casters);
    draws += counts.drawn;
    culled += counts.culled;
  };
  if (single_pass) {
    // 1. All six faces attached at once (layered); the geometry shader picks the face per triangle.
    glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0);
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glClearBufferfv(GL_COLOR, 0, empty);  // clears every layer
    glClearBufferfv(GL_DEPTH, 0, &far_depth);
    if (layered_u_.generation != layered_.generation()) {
      layered_u_ = {layered_.generation(), Uniform(layered_.id(), "u_face_view_proj"),
                    Uniform(layered_.id(), "u_light_position")};
    }
    glUseProgram(layered_.id());
    if (layered_u_.face_view_proj.present())
      glUniformMatrix4fv(glGetUniformLocation(layered_.id(), "u_face_view_proj[0]"), 6, GL_FALSE, &view_proj[0][0][0]);
    layered_u_.light_position.set(light_position);
    draw_casters(view_proj, 6);
    faces += 6;
  } else {
    // 1..6. One face at a time: attach its layer, clear it, draw the scene through that face's view.
    if (faces_u_.generation != faces_.generation()) {
      faces_u_ = {faces_.generation(), Uniform(faces_.id(), "u_light_view_proj"), Uniform(faces_.id(), "u_light_position")};
    }
    glUseProgram(faces_.id());
    faces_u_.light_position.set(light_position);
    for (int f = 0; f < 6; ++f) {
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0, f);
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0, f);
      glClearBufferfv(GL_COLOR, 0, empty);
      glClearBufferfv(GL_DEPTH, 0, &far_depth);
      faces_u_.light_view_proj.set(view_proj[f]);
      draw_casters(&view_proj[f], 1);
      ++faces;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<float> CubeShadowPass::read_face(int face) const {
  std::vector<float> data(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_));
  GlFramebuffer read = GlFramebuffer::create();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read.id());
  glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0, face);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size_, size_, GL_RED, GL_FLOAT, data.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return data;
}

}  // namespace shadowlab
