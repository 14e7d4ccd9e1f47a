#include "renderer/shadow_volume_pass.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/adjacency.h"
#include "renderer/volume_stencil.h"

namespace shadowlab {

ShadowVolumePass::ShadowVolumePass()
    : program_({"shaders/volume/volume.vert", "shaders/volume/extrude.geom", "shaders/volume/volume.frag", {},
                {{"lab/volume.glsl", "shaders/volume/volume.glsl"}}, {}, {"v_world_corner"}}),
      vao_(GlVertexArray::create()),
      positions_(GlBuffer::create()),
      indices_(GlBuffer::create()) {}

std::map<std::string, std::string> ShadowVolumePass::default_includes(LightType) {
  // Visibility is decided by the stencil test before the lit pass runs.
  return {{"lab/bias.glsl", "shaders/shadow/bias.glsl"},
          {"lab/visibility.glsl", "shaders/volume/stencil_visibility.glsl"},
          {"lab/volume.glsl", "shaders/volume/volume.glsl"}};
}

void ShadowVolumePass::for_each_program(const std::function<void(ReloadableProgram&)>& f) { f(program_); }

void ShadowVolumePass::draw_view_passes(PassContext& ctx, const ViewTarget& view) {
  const bool z_fail = ctx.params.get(param::volume_method) == "z-fail";
  // 1. The scene with ambient light only (colour, depth and the G-buffer, visibility 0) is drawn by the
  // renderer first (shape().lit_first). 2. The volumes into the stencil buffer.
  ctx.timed("volumes", [&] {
    glBindFramebuffer(GL_FRAMEBUFFER, view.framebuffer);
    glViewport(0, 0, view.width, view.height);
    draw_stencil(ctx.camera_view_proj(), ctx.light.vector4(), z_fail, ctx.stats.draws);
  });
  ++ctx.stats.stencil_passes;
}

LitBind ShadowVolumePass::lit_bind(GLuint) const {
  return [](const ParamSet&) {  // no map: the stencil says what is shadowed
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
  };
}

std::vector<std::uint8_t> ShadowVolumePass::image(int* size) const {
  *size = 16;
  return std::vector<std::uint8_t>(16 * 16 * 4, 128);
}

bool ShadowVolumePass::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  ProgramDesc d = program_.desc();
  d.includes = includes;
  d.rules = rules;
  if (!d.includes.count("lab/volume.glsl")) d.includes["lab/volume.glsl"] = "shaders/volume/volume.glsl";
  program_.set_desc(std::move(d));
  return program_.rebuild();
}

void ShadowVolumePass::set_scene(const Scene& scene) {
  std::vector<glm::vec3> positions;
  std::vector<std::uint32_t> indices;
  report_.clear();
  for (const Mesh& mesh : scene.meshes) {
    if (!mesh.casts_shadow || mesh.triangle_count() == 0) continue;  // the oracle ignores them too
    const Adjacency adjacency = build_adjacency(mesh);
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (std::uint32_t i : adjacency.indices) indices.push_back(base + i);
    report_.push_back({mesh.name, mesh.triangle_count(), adjacency.edges, adjacency.open_edges,
                       adjacency.non_manifold_edges, adjacency.inconsistent_edges});
  }
  glBindVertexArray(vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, positions_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(positions.size() * sizeof(glm::vec3)), positions.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindVertexArray(0);
  index_count_ = indices.size();
}

void ShadowVolumePass::use_program(const glm::mat4& view_proj, const glm::vec4& light, bool caps, const glm::vec4& color) {
  if (!program_.valid()) throw std::runtime_error("shadow volume program failed to build:\n" + program_.error());
  if (u_.generation != program_.generation()) {
    const GLuint id = program_.id();
    u_ = {program_.generation(), Uniform(id, "u_view_proj"), Uniform(id, "u_light"), Uniform(id, "u_caps"),
          Uniform(id, "u_color")};
  }
  glUseProgram(program_.id());
  u_.view_proj.set(view_proj);
  u_.light.set(light);
  u_.caps.set(caps ? 1 : 0);
  u_.color.set(color);
}

void ShadowVolumePass::draw_adjacency(long& draws) {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES_ADJACENCY, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
  ++draws;
}

void ShadowVolumePass::draw_volumes(const glm::mat4& view_proj, const glm::vec4& light, bool caps,
                                    const glm::vec4& color, long& draws) {
  use_program(view_proj, light, caps, color);
  draw_adjacency(draws);
}

void ShadowVolumePass::draw_stencil(const glm::mat4& view_proj, const glm::vec4& light, bool z_fail, long& draws) {
  // 2. The counting pass's state is renderer/volume_stencil.cpp's (lab 9's GL exercise). The near caps
  // lie exactly on the occluders' lit faces: pushing the volumes a hair back makes those faces fail the
  // depth test consistently instead of fighting over equal depths. A constant offset only
  // (kVolumeOffsetUnits): a slope-scaled one pushes each side quad back by its own depth slope, up to a
  // pixel's worth, and moves every shadow outline on a receiver by up to a pixel (lab 9's INSTRUCTOR.md:
  // with glPolygonOffset(1, 1) the benchmark's frame had 190 wrong pixels on the default scene, with this 28).
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, kVolumeOffsetUnits);
  // Handed over by reference: a std::function holding the lambda itself would allocate every frame (its
  // captures outgrow the small buffer; RendererTest.StillFramesAllocateNothing), one holding a
  // reference_wrapper does not.
  const auto draw = [&] { draw_volumes(view_proj, light, z_fail, glm::vec4(0.0f), draws); };
  code_.stencil_pass(z_fail, std::cref(draw));
  glDisable(GL_POLYGON_OFFSET_FILL);
}

VolumeTriangles ShadowVolumePass::count_triangles(const glm::vec4& light, bool caps, const Bounds& box) {
  // Each input triangle emits at most max_vertices = 18 vertices: a strip of at most 16 triangles, each
  // captured as its three corners in world space (v_world_corner).
  const std::size_t most = index_count_ / 6 * 16 * 3 * 4;
  GlBuffer feedback = GlBuffer::create();
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, feedback.id());
  glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(most, 12) * sizeof(float)),
               nullptr, GL_STATIC_READ);
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, feedback.id());
  GlQuery written = GlQuery::create();
  glEnable(GL_RASTERIZER_DISCARD);
  glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, written.id());
  use_program(glm::mat4(1.0f), light, caps, glm::vec4(0.0f));  // before: no program change while capturing
  glBeginTransformFeedback(GL_TRIANGLES);
  long draws = 0;
  draw_adjacency(draws);
  glEndTransformFeedback();
  glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
  glDisable(GL_RASTERIZER_DISCARD);
  GLuint64 triangles = 0;
  glGetQueryObjectui64v(written.id(), GL_QUERY_RESULT, &triangles);
  std::vector<glm::vec4> corners(static_cast<std::size_t>(triangles) * 3);
  if (!corners.empty())
    glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, static_cast<GLsizeiptr>(corners.size() * sizeof(glm::vec4)),
                       corners.data());
  glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
  glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
  // On the occluders: finite and inside the box, grown by a thousandth of its size for rounding.
  const glm::vec3 slack = 1e-3f * (box.max - box.min) + glm::vec3(1e-6f);
  const auto on_occluders = [&](const glm::vec4& c) {
    if (c.w == 0.0f) return false;
    const glm::vec3 p = glm::vec3(c) / c.w;
    return glm::all(glm::greaterThanEqual(p, box.min - slack)) && glm::all(glm::lessThanEqual(p, box.max + slack));
  };
  VolumeTriangles count;
  for (std::size_t t = 0; t < static_cast<std::size_t>(triangles); ++t) {
    int on = 0;
    for (std::size_t v = 0; v < 3; ++v) on += on_occluders(corners[3 * t + v]);
    (on == 3 ? count.near_caps : on == 0 ? count.far_caps : count.sides) += 1;
  }
  return count;
}

void ShadowVolumePass::draw_wireframe(const glm::mat4& view_proj, const glm::vec4& light, bool caps, long& draws) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_DEPTH_CLAMP);
  glDisable(GL_CULL_FACE);
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  draw_volumes(view_proj, light, caps, glm::vec4(1.0f, 0.85f, 0.1f, 1.0f), draws);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glDisable(GL_DEPTH_CLAMP);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

}  // namespace shadowlab
