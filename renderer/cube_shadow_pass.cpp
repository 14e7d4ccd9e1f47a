#include "renderer/cube_shadow_pass.h"

#include <algorithm>
#include <stdexcept>

namespace shadowlab {

namespace {

constexpr const char* kStoreInclude = "lab/cube_store.glsl";
constexpr const char* kDefaultStore = "shaders/cube/store.glsl";

// Six layers, one per cube face in GL's order (the lit pass selects the face itself: lab 8).
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
                {{"LAYERED", "1"}}, {{kStoreInclude, kDefaultStore}}}),
      faces_mask_(faces_.desc()),
      layered_mask_(layered_.desc()),
      face_quad_({"shaders/fullscreen.vert", {}, "shaders/debug/cube_face.frag", {}, {}}) {
  if (!faces_.rebuild() || !layered_.rebuild())
    throw std::runtime_error("cannot build the cube shadow pass's shaders:\n" + faces_.error() + layered_.error());
}

std::map<std::string, std::string> CubeShadowPass::default_includes(LightType) {
  return {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
          {"lab/visibility.glsl", "shaders/shadow/cube.glsl"},
          {kStoreInclude, kDefaultStore}};
}

bool CubeShadowPass::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  // The distance programs include what the faces store (lab 8's part 1): a file that does not compile is
  // reported here, not at the first frame.
  bool ok = true;
  for (ReloadableProgram* p : {&faces_, &layered_}) {
    ProgramDesc d = p->desc();
    d.includes = includes;
    d.rules = rules;
    if (!d.includes.count(kStoreInclude)) d.includes[kStoreInclude] = kDefaultStore;
    p->set_desc(std::move(d));
    ok = p->rebuild() && ok;
  }
  ok = faces_mask_.follow(faces_.desc()) && ok;
  ok = layered_mask_.follow(layered_.desc()) && ok;
  return face_quad_.rebuild() && ok;
}

void CubeShadowPass::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(faces_);
  f(layered_);
  f(face_quad_);
  faces_mask_.for_each_program(f);
  layered_mask_.for_each_program(f);
}

bool CubeShadowPass::ensure_targets(const ParamSet& params) {
  return ensure_targets(std::stoi(params.get(param::shadow_map_size)));
}

void CubeShadowPass::draw_map(PassContext& ctx) {
  const bool single = ctx.params.get(param::point_single_pass);
  far_plane_ = ctx.light.cube.far_plane;
  ctx.timed("cube_shadow", [&] {
    ctx.count_texels([&] {
      draw(ctx.gpu_scene, ctx.light.cube, ctx.light.position, single, ctx.params.get(param::shadow_cull_casters),
           ctx.stats.draws, ctx.stats.cube_faces, ctx.stats.casters_culled);
    });
  });
}

LitBind CubeShadowPass::lit_bind(GLuint program) const {
  return [this, faces = Uniform(program, "u_shadow_faces")](const ParamSet&) {
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D_ARRAY, distance_.id());
    faces.set(2);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
  };
}

void CubeShadowPass::draw_debug_quads(const DebugQuadArea& area) {
  if (face_quad_u_.generation != face_quad_.generation()) {
    const GLuint id = face_quad_.id();
    face_quad_u_ = {face_quad_.generation(), Uniform(id, "u_cube"), Uniform(id, "u_face"), Uniform(id, "u_far")};
  }
  const int cell = area.side / 2;
  glUseProgram(face_quad_.id());
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, distance_.id());
  face_quad_u_.cube.set(0);
  face_quad_u_.far_plane.set(std::max(far_plane_, 1e-6f));
  glBindVertexArray(area.empty_vao);
  for (int f = 0; f < 6; ++f) {
    static constexpr const char* kFaceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};  // GL's layer order
    area.place(area.width - 8 - (3 - f % 3) * (cell + 4), 8 + (f < 3 ? cell + 4 : 0), cell, cell,
               std::string(kFaceNames[f]) + " face: distance");
    face_quad_u_.face.set(f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
}

std::vector<std::uint8_t> CubeShadowPass::image(int* size) const {
  const int n = size_, half = std::max(n / 2, 1);
  *size = 3 * half;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(*size) * static_cast<std::size_t>(*size) * 4, 255);
  const float range = std::max(far_plane_, 1e-6f);
  for (int f = 0; f < 6; ++f) {
    const std::vector<float> d = read_face(f);
    const int ox = (f % 3) * half, oy = (f / 3) * half;  // oy counted from the top
    for (int y = 0; y < half; ++y)
      for (int x = 0; x < half; ++x) {
        const float v = d[static_cast<std::size_t>(2 * y) * n + 2 * x];
        const int row = oy + (half - 1 - y);  // face rows are bottom first
        const std::size_t i = (static_cast<std::size_t>(row) * static_cast<std::size_t>(*size) + ox + x) * 4;
        const auto g = static_cast<std::uint8_t>(v >= kCubeEmptyDistance ? 255.0f : std::clamp(v / range, 0.0f, 1.0f) * 230.0f);
        rgba[i] = rgba[i + 1] = rgba[i + 2] = g;
      }
  }
  return rgba;
}

bool CubeShadowPass::ensure_targets(int size) {
  if (size == size_ && distance_) return false;
  distance_ = make_faces(GL_R32F, GL_RED, size);
  depth_ = make_faces(GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, size);
  fbo_ = GlFramebuffer::create();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0);  // layered: all six faces
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
  auto draw_casters = [&](const glm::mat4* faces_view_proj, int count, const AlphaMaskVariant::Callback* masked) {
    const auto counts = scene.draw_casters(faces_view_proj, count, cull_casters, masked);
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
    draw_casters(view_proj, 6, layered_mask_.prepare(scene, [&](AlphaMaskVariant& v) {
      glUniformMatrix4fv(v.location("u_face_view_proj[0]"), 6, GL_FALSE, &view_proj[0][0][0]);
      v.set("u_light_position", light_position);
    }));
    faces += 6;
  } else {
    // 1..6. One face at a time: attach it, clear it, draw the scene through that face's view.
    if (faces_u_.generation != faces_.generation()) {
      faces_u_ = {faces_.generation(), Uniform(faces_.id(), "u_light_view_proj"), Uniform(faces_.id(), "u_light_position")};
    }
    glUseProgram(faces_.id());
    faces_u_.light_position.set(light_position);
    for (int f = 0; f < 6; ++f) {
      glUseProgram(faces_.id());  // again each face: its alpha-tested casters end on faces_mask_'s program
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0, f);
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0, f);
      glClearBufferfv(GL_COLOR, 0, empty);
      glClearBufferfv(GL_DEPTH, 0, &far_depth);
      faces_u_.light_view_proj.set(view_proj[f]);
      draw_casters(&view_proj[f], 1, faces_mask_.prepare(scene, [&](AlphaMaskVariant& v) {
        v.set("u_light_view_proj", view_proj[f]);
        v.set("u_light_position", light_position);
      }));
      ++faces;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

std::vector<float> CubeShadowPass::read_face(int face) const {
  GlFramebuffer read = GlFramebuffer::create();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, read.id());
  glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, distance_.id(), 0, face);
  return read_pixels(read.id(), GL_COLOR_ATTACHMENT0, size_, size_, GL_RED, 1);
}

}  // namespace shadowlab
