#include "renderer/debug_views.h"

#include <algorithm>
#include <stdexcept>

#include "renderer/lit_pass.h"
#include "renderer/shadowed_light.h"

namespace shadowlab {

ProgramDesc DebugViews::flat_normals_desc() {
  return {"shaders/debug/normals.vert", "shaders/debug/flat_normals.geom", "shaders/debug/flat_normals.frag", {}, {}};
}

DebugViews::DebugViews()
    : flat_normals_(flat_normals_desc()),
      normals_({"shaders/debug/normals.vert", "shaders/debug/normals.geom", "shaders/debug/normals.frag", {}, {}}),
      lines_({"shaders/debug/lines.vert", {}, "shaders/debug/lines.frag", {}, {}}) {
  if (!flat_normals_.rebuild() || !normals_.rebuild() || !lines_.rebuild())
    throw std::runtime_error("cannot build the debug views' shaders:\n" + flat_normals_.error() + normals_.error() +
                             lines_.error());
}

void DebugViews::for_each_program(const std::function<void(ReloadableProgram&)>& f) {
  f(flat_normals_);
  f(normals_);
  f(lines_);
  if (wireframe_volumes_) wireframe_volumes_->for_each_program(f);
}

void DebugViews::set_includes(const IncludeMap& includes, const IncludeRules& rules) {
  includes_ = includes;
  rules_ = rules;
  wireframe_volumes_.reset();
}

std::vector<VolumeMeshReport> DebugViews::volume_report() const {
  return wireframe_volumes_ ? wireframe_volumes_->report() : std::vector<VolumeMeshReport>{};
}

void DebugViews::draw(PassContext& ctx, ShadowPass& shadow, LitPass& lit) {
  const ParamSet& params = ctx.params;
  // The technique's own false-colour view, drawn by the lit pass where the technique asks for it.
  if (std::optional<LitView> view = shadow.lit_view(params)) {
    ctx.timed(view->draw.name, [&] { lit.draw(ctx, view->draw.variant); });
    if (ctx.annotations) ctx.annotations->legends.push_back(std::move(view->legend));
  }
  // The facets first, so the normals' lines are drawn over them.
  if (params.get(param::view_flat_normals)) ctx.timed("flat_normals_view", [&] { flat_normals(ctx, lit); });
  if (params.get(param::view_normals)) ctx.timed("normals_view", [&] { normals(ctx, lit); });
  if (params.get(param::view_volumes)) ctx.timed("volumes_view", [&] { volumes_wireframe(ctx, shadow, lit); });
  // A point light's six frusta fill all space: nothing to draw.
  if (params.get(param::view_light_volume) && ctx.light.type != LightType::Point)
    ctx.timed("light_volume_view", [&] { light_volume(ctx, lit); });
  if (shadow.shape().has_map && params.get(param::view_debug_quad))
    ctx.timed("debug_quad", [&] { debug_quads(ctx, lit); });
}

void DebugViews::flat_normals(PassContext& ctx, LitPass& lit) {
  if (flat_normals_u_.generation != flat_normals_.generation())
    flat_normals_u_ = {flat_normals_.generation(), Uniform(flat_normals_.id(), "u_view_proj")};
  bind_color_target(lit.framebuffer(), lit.width(), lit.height());  // over the picture; the G-buffer stays as drawn
  // The same triangles as the lit pass, redrawn over it: pulled a little toward the eye so that they win
  // the depth test against their own depths (another program need not compute bit-identical depths).
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -1.0f);
  glUseProgram(flat_normals_.id());
  flat_normals_u_.view_proj.set(ctx.camera_view_proj());
  ctx.gpu_scene.bind();
  for (const auto& range : ctx.gpu_scene.ranges()) {
    ctx.gpu_scene.draw(range);
    ++ctx.stats.draws;
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, 0.0f);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void DebugViews::normals(PassContext& ctx, LitPass& lit) {
  if (normals_u_.generation != normals_.generation())
    normals_u_ = {normals_.generation(), Uniform(normals_.id(), "u_view_proj"), Uniform(normals_.id(), "u_normal_length")};
  bind_color_target(lit.framebuffer(), lit.width(), lit.height());  // lines over the picture; the G-buffer stays as drawn
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  glUseProgram(normals_.id());
  normals_u_.view_proj.set(ctx.camera_view_proj());
  // A few percent of the scene's size: long enough to see, short enough not to hide the scene.
  const Bounds& b = ctx.gpu_scene.bounds();
  normals_u_.length.set(b.empty() ? 0.1f : 0.03f * glm::length(b.extent()));
  ctx.gpu_scene.bind();
  for (const auto& range : ctx.gpu_scene.ranges()) {
    ctx.gpu_scene.draw(range);
    ++ctx.stats.draws;
  }
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
}

void DebugViews::volumes_wireframe(PassContext& ctx, ShadowPass& shadow, LitPass& lit) {
  // The shadow-volume technique's own volumes (what the frame's stencil counted), else the view's.
  auto* volumes = dynamic_cast<ShadowVolumePass*>(&shadow);
  if (!volumes) {
    if (!wireframe_volumes_) {
      wireframe_volumes_ = std::make_unique<ShadowVolumePass>();
      wireframe_volumes_->set_includes(includes_, rules_);
      wireframe_scene_stale_ = true;
    }
    if (wireframe_scene_stale_) {
      wireframe_volumes_->set_scene(ctx.scene);
      wireframe_scene_stale_ = false;
    }
    volumes = wireframe_volumes_.get();
  }
  bind_color_target(lit.framebuffer(), lit.width(), lit.height());
  // Lines running to infinity need the infinite far plane, whatever the technique drew with; the depth
  // test against the scene is then only approximate for the other techniques (a different projection).
  glm::mat4 projection = ctx.camera_projection;  // the same field of view, its far plane moved to infinity
  const float near_plane = projection[3][2] / (projection[2][2] - 1.0f);
  projection[2][2] = -1.0f;
  projection[3][2] = -2.0f * near_plane;
  const glm::mat4 view_proj = (ctx.infinite_far_plane ? ctx.camera_projection : projection) * ctx.camera_view;
  if (!ctx.infinite_far_plane) glDisable(GL_DEPTH_TEST);
  const bool caps = ctx.params.get(param::volume_method) == "z-fail";
  volumes->draw_wireframe(view_proj, ctx.light.vector4(), caps, ctx.stats.draws);
  glEnable(GL_DEPTH_TEST);
}

void DebugViews::light_volume(PassContext& ctx, LitPass& lit) {
  // The 12 edges of the shadow map's volume: the clip cube [-1, 1]^3 taken back to world space through
  // the inverse of the light's view-projection (an ortho box or a spot's frustum alike).
  const glm::mat4 to_world = glm::inverse(ctx.light.view.view_projection());
  glm::vec3 corner[8];
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = to_world * glm::vec4((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f);
    corner[i] = glm::vec3(c) / c.w;
  }
  std::vector<glm::vec3> lines;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) lines.insert(lines.end(), {corner[i], corner[i | bit]});
  if (!lines_vao_) {
    lines_vao_ = GlVertexArray::create();
    lines_vbo_ = GlBuffer::create();
    glBindVertexArray(lines_vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, lines_vbo_.id());
    glBufferData(GL_ARRAY_BUFFER, 24 * sizeof(glm::vec3), nullptr, GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  }
  glBindVertexArray(lines_vao_.id());
  glBindBuffer(GL_ARRAY_BUFFER, lines_vbo_.id());
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(lines.size() * sizeof(glm::vec3)), lines.data());
  if (lines_u_.generation != lines_.generation())
    lines_u_ = {lines_.generation(), Uniform(lines_.id(), "u_view_proj"), Uniform(lines_.id(), "u_color")};
  bind_color_target(lit.framebuffer(), lit.width(), lit.height());
  glDisable(GL_DEPTH_TEST);  // the whole box, also where the scene hides it
  glUseProgram(lines_.id());
  lines_u_.view_proj.set(ctx.camera_view_proj());
  lines_u_.color.set(glm::vec4(1.0f, 0.85f, 0.2f, 1.0f));
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size()));
  ++ctx.stats.draws;
  glEnable(GL_DEPTH_TEST);
}

void DebugQuadArea::place(int x, int y, int quad_width, int quad_height, const std::string& label) const {
  glViewport(x, y, quad_width, quad_height);
  if (labels) labels->push_back({x, y, quad_width, quad_height, light.empty() ? label : light + ": " + label});
}

void DebugViews::debug_quads(PassContext& ctx, LitPass& lit) {
  bind_color_target(lit.framebuffer(), lit.width(), lit.height());  // the quads must not overwrite the G-buffer
  glDisable(GL_DEPTH_TEST);
  // Squares along the bottom right (clear of an overlay on the left), view.debug_quad_size of the frame height.
  const int side =
      std::max(8, static_cast<int>(static_cast<float>(lit.height()) * ctx.params.get(param::view_debug_quad_size)));
  std::vector<DebugQuadLabel>* labels = ctx.annotations ? &ctx.annotations->quads : nullptr;
  // Each light's map, the frame light's at the right (the view.debug_channel of its technique), each further
  // one's depth left of the one before; beside other lights' maps, each says whose it is.
  const std::size_t count = ctx.lights ? ctx.lights->size() : 0;
  int right = lit.width();
  for (std::size_t i = 0; i < count; ++i) {
    ShadowedLight& light = (*ctx.lights)[i];
    const bool frame = i == 0;
    light.pass().draw_debug_quads({right, lit.height(), side, frame ? ctx.params.get(param::view_debug_channel) : "depth",
                                   ctx.empty_vao, count > 1 ? light.name() : "", labels});
    right -= side + 8;
  }
  glEnable(GL_DEPTH_TEST);
  glViewport(0, 0, lit.width(), lit.height());
}

}  // namespace shadowlab
